#include "ancfnet/contact/laws/normal_law.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

bool IsDissipative(NormalLawKind kind) {
  return kind != NormalLawKind::kLinear && kind != NormalLawKind::kHertz;
}

void RequirePositiveFinite(double value, const std::string& name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError("contact law: " + name + " must be positive and finite, got " +
                     std::to_string(value));
  }
}

}  // namespace

double CalcHysteresisFactor(NormalLawKind kind, double e) {
  switch (kind) {
    case NormalLawKind::kLinear:
    case NormalLawKind::kHertz:
      return 0.0;
    case NormalLawKind::kHuntCrossley:
      return 1.5 * (1.0 - e);
    case NormalLawKind::kLankaraniNikravesh:
      return 0.75 * (1.0 - e * e);
    case NormalLawKind::kFlores:
      return 8.0 * (1.0 - e) / (5.0 * e);
    case NormalLawKind::kGonthier:
      return (1.0 - e * e) / e;
    case NormalLawKind::kCarvalhoMartins:
      return 1.5 * (1.0 - e) * (11.0 - e) / (1.0 + 9.0 * e);
  }
  return 0.0;
}

double CalcRestitutionForHysteresisFactor(double chi) {
  if (!(chi >= 0.0) || !std::isfinite(chi)) {
    throw InputError("contact law: the hysteresis factor must be non-negative and finite, got " +
                     std::to_string(chi));
  }
  if (chi == 0.0) return 1.0;
  // r(e) = χ(1 + e) − ln(1 + χ) + ln(1 − χe) is concave in e with r(0) > 0 and r → −∞ as
  // e → 1/χ, so its root in (0, min(1, 1/χ)) is bracketed; bisection to machine precision.
  const auto residual = [chi](double e) {
    return chi * (1.0 + e) - std::log1p(chi) + std::log1p(-chi * e);
  };
  double lo = 0.0;
  double hi = std::min(1.0, 1.0 / chi);
  if (residual(hi) >= 0.0) return hi;  // only for χ → 0, where e* → 1
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double NormalLaw::hysteresis_factor() const { return CalcHysteresisFactor(kind, restitution); }

NormalForce NormalLaw::Evaluate(double delta, double delta_dot, double approach_speed) const {
  NormalForce out;
  if (delta <= 0.0) return out;
  if (kind == NormalLawKind::kLinear) {
    out.elastic_force = stiffness * delta;
    const double f = out.elastic_force + damping * delta_dot;
    if (f <= 0.0) return out;  // the dashpot would pull: the bodies part force-free
    out.force = f;
    out.dforce_ddelta = stiffness;
    out.dforce_ddelta_dot = damping;
    return out;
  }
  const double pow_n = std::pow(delta, exponent);
  out.elastic_force = stiffness * pow_n;
  const double dpow_n = exponent * pow_n / delta;  // n δⁿ⁻¹ without 0·∞ at n < 1
  if (kind == NormalLawKind::kHertz) {
    out.force = out.elastic_force;
    out.dforce_ddelta = stiffness * dpow_n;
    return out;
  }
  const double v0 = std::max(approach_speed, min_approach_speed);
  const double chi_over_v0 = hysteresis_factor() / v0;
  const double factor = 1.0 + chi_over_v0 * delta_dot;
  if (factor <= 0.0) return out;
  out.force = out.elastic_force * factor;
  out.dforce_ddelta = stiffness * dpow_n * factor;
  out.dforce_ddelta_dot = out.elastic_force * chi_over_v0;
  return out;
}

double NormalLaw::CalcElasticEnergy(double delta) const {
  if (delta <= 0.0) return 0.0;
  if (kind == NormalLawKind::kLinear) return 0.5 * stiffness * delta * delta;
  return stiffness * std::pow(delta, exponent + 1.0) / (exponent + 1.0);
}

void ValidateNormalLaw(const NormalLaw& law) {
  RequirePositiveFinite(law.stiffness, "stiffness k");
  if (law.kind == NormalLawKind::kLinear) {
    if (law.exponent != 1.0) throw InputError("contact law: a linear law has exponent 1");
    if (!(law.damping >= 0.0) || !std::isfinite(law.damping)) {
      throw InputError("contact law: damping c must be non-negative and finite, got " +
                       std::to_string(law.damping));
    }
    return;
  }
  RequirePositiveFinite(law.exponent, "exponent n");
  if (!IsDissipative(law.kind)) return;
  if (!(law.restitution > 0.0 && law.restitution <= 1.0)) {
    throw InputError("contact law: coefficient of restitution e must be in (0, 1], got " +
                     std::to_string(law.restitution));
  }
  RequirePositiveFinite(law.min_approach_speed, "minimum approach speed");
}

NormalLaw MakeLinearContactLaw(double stiffness, double damping) {
  NormalLaw law;
  law.kind = NormalLawKind::kLinear;
  law.stiffness = stiffness;
  law.exponent = 1.0;
  law.damping = damping;
  ValidateNormalLaw(law);
  return law;
}

NormalLaw MakeHertzContactLaw(double stiffness, double exponent) {
  NormalLaw law;
  law.kind = NormalLawKind::kHertz;
  law.stiffness = stiffness;
  law.exponent = exponent;
  ValidateNormalLaw(law);
  return law;
}

NormalLaw MakeDissipativeContactLaw(NormalLawKind kind, double stiffness, double restitution,
                                    double exponent, double min_approach_speed) {
  if (!IsDissipative(kind)) {
    throw InputError("contact law: MakeDissipativeContactLaw needs a dissipative kind");
  }
  NormalLaw law;
  law.kind = kind;
  law.stiffness = stiffness;
  law.exponent = exponent;
  law.restitution = restitution;
  law.min_approach_speed = min_approach_speed;
  ValidateNormalLaw(law);
  return law;
}

}  // namespace ancfnet
