#include "ancfnet/contact/laws/friction_law.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/contact/laws/bristle_friction.hpp"

namespace ancfnet {
namespace {

double Sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

bool IsFinite(double x) { return std::isfinite(x); }

void Require(bool ok, const std::string& message, double value) {
  if (!ok) throw InputError("friction law: " + message + ", got " + std::to_string(value));
}

void ValidateStribeck(const FrictionLaw& law, bool kinetic_positive) {
  const double mu_k = law.kinetic_coefficient;
  Require(IsFinite(mu_k) && (kinetic_positive ? mu_k > 0.0 : mu_k >= 0.0),
          kinetic_positive ? "kinetic coefficient must be positive and finite"
                           : "kinetic coefficient must be non-negative and finite",
          mu_k);
  Require(IsFinite(law.static_coefficient) && law.static_coefficient >= mu_k,
          "static coefficient must be finite and at least the kinetic one", law.static_coefficient);
  Require(IsFinite(law.stribeck_speed) && law.stribeck_speed > 0.0,
          "Stribeck speed must be positive and finite", law.stribeck_speed);
}

}  // namespace

double FrictionLaw::CalcStribeck(double speed, double* dstribeck_dspeed) const {
  const double ratio = speed / stribeck_speed;
  const double hump = (static_coefficient - kinetic_coefficient) * std::exp(-ratio * ratio);
  if (dstribeck_dspeed != nullptr) *dstribeck_dspeed = -2.0 * hump * ratio / stribeck_speed;
  return kinetic_coefficient + hump;
}

FrictionForce FrictionLaw::Evaluate(double v, double normal_force) const {
  FrictionForce out;
  if (kind == FrictionLawKind::kLuGre) {
    throw std::logic_error("FrictionLaw::Evaluate: a LuGre law has a state; use StepBristle");
  }
  if (normal_force <= 0.0) return out;
  const double s = std::abs(v);
  double mu = 0.0;  // μ(v) with F_t = −N μ(v), odd in v
  double dmu_dv = 0.0;
  if (kind == FrictionLawKind::kAmbrosio) {
    const double v0 = ramp_start_speed;
    const double v1 = ramp_end_speed;
    if (s >= v1) {
      mu = kinetic_coefficient * Sign(v);
    } else if (s > v0) {
      mu = kinetic_coefficient * (s - v0) / (v1 - v0) * Sign(v);
      dmu_dv = kinetic_coefficient / (v1 - v0);
    }
  } else {
    double dg = 0.0;
    const double g = CalcStribeck(s, &dg);
    const double t = std::tanh(v / regularization_speed);
    mu = g * t;
    dmu_dv = dg * Sign(v) * t + g * (1.0 - t * t) / regularization_speed;
  }
  out.force = -normal_force * mu;
  out.dforce_dvelocity = -normal_force * dmu_dv;
  out.dforce_dnormal = -mu;
  return out;
}

BristleStep FrictionLaw::StepBristle(double z0, double v, double normal_force, double h) const {
  if (kind != FrictionLawKind::kLuGre) {
    throw std::logic_error("FrictionLaw::StepBristle: only a LuGre law has a bristle state");
  }
  if (!(h > 0.0)) throw std::logic_error("FrictionLaw::StepBristle: the step must be positive");
  // The slip along one axis of the tangent plane.
  const TangentialBristleStep step = CalcTangentialBristleFriction(
      *this, Vector3d(z0, 0.0, 0.0), Vector3d(v, 0.0, 0.0), normal_force, h);
  BristleStep out;
  out.deflection = step.deflection.x();
  out.friction.force = step.friction.force.x();
  out.friction.dforce_dvelocity = step.friction.dforce_dvelocity(0, 0);
  out.friction.dforce_dnormal = step.friction.dforce_dnormal.x();
  return out;
}

void ValidateFrictionLaw(const FrictionLaw& law) {
  switch (law.kind) {
    case FrictionLawKind::kAmbrosio:
      Require(IsFinite(law.kinetic_coefficient) && law.kinetic_coefficient >= 0.0,
              "friction coefficient must be non-negative and finite", law.kinetic_coefficient);
      Require(IsFinite(law.ramp_start_speed) && law.ramp_start_speed >= 0.0,
              "ramp start speed v0 must be non-negative and finite", law.ramp_start_speed);
      Require(IsFinite(law.ramp_end_speed) && law.ramp_end_speed > law.ramp_start_speed,
              "ramp end speed v1 must be finite and above v0", law.ramp_end_speed);
      return;
    case FrictionLawKind::kTanh:
      ValidateStribeck(law, false);
      Require(IsFinite(law.regularization_speed) && law.regularization_speed > 0.0,
              "regularisation speed must be positive and finite", law.regularization_speed);
      return;
    case FrictionLawKind::kLuGre:
      ValidateStribeck(law, true);
      Require(IsFinite(law.bristle_stiffness) && law.bristle_stiffness > 0.0,
              "bristle stiffness sigma0 must be positive and finite", law.bristle_stiffness);
      Require(IsFinite(law.bristle_damping) && law.bristle_damping >= 0.0,
              "bristle damping sigma1 must be non-negative and finite", law.bristle_damping);
      Require(IsFinite(law.viscous_damping) && law.viscous_damping >= 0.0,
              "viscous damping sigma2 must be non-negative and finite", law.viscous_damping);
      return;
  }
}

FrictionLaw MakeAmbrosioFriction(double coefficient, double ramp_start_speed,
                                 double ramp_end_speed) {
  FrictionLaw law;
  law.kind = FrictionLawKind::kAmbrosio;
  law.static_coefficient = coefficient;
  law.kinetic_coefficient = coefficient;
  law.ramp_start_speed = ramp_start_speed;
  law.ramp_end_speed = ramp_end_speed;
  ValidateFrictionLaw(law);
  return law;
}

FrictionLaw MakeTanhFriction(double static_coefficient, double kinetic_coefficient,
                             double regularization_speed, double stribeck_speed) {
  FrictionLaw law;
  law.kind = FrictionLawKind::kTanh;
  law.static_coefficient = static_coefficient;
  law.kinetic_coefficient = kinetic_coefficient;
  law.regularization_speed = regularization_speed;
  law.stribeck_speed = stribeck_speed;
  ValidateFrictionLaw(law);
  return law;
}

FrictionLaw MakeLuGreFriction(double static_coefficient, double kinetic_coefficient,
                              double stribeck_speed, double bristle_stiffness,
                              double bristle_damping, double viscous_damping) {
  FrictionLaw law;
  law.kind = FrictionLawKind::kLuGre;
  law.static_coefficient = static_coefficient;
  law.kinetic_coefficient = kinetic_coefficient;
  law.stribeck_speed = stribeck_speed;
  law.bristle_stiffness = bristle_stiffness;
  law.bristle_damping = bristle_damping;
  law.viscous_damping = viscous_damping;
  ValidateFrictionLaw(law);
  return law;
}

}  // namespace ancfnet
