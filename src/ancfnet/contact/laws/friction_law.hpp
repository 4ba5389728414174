#pragma once
/// @file Friction laws: the tangential force F_t (N) on a body that slips with velocity v (m/s)
/// along the tangent of a contact that presses with the normal force N ≥ 0 (N). F_t opposes v.
/// Two regularised Coulomb laws, F_t = −N μ(v), with no state, and one bristle (LuGre) law with
/// an internal deflection z that gives true stiction below μ_s N. The laws are scalar (one slip
/// direction); docs/theory.md, "Contact force laws", gives the equations and the creep that each
/// regularised law allows. A law is a plain value built once by a Make… factory (which validates
/// it) and evaluated without allocating.

namespace ancfnet {

/// The closed list of friction laws.
enum class FrictionLawKind {
  /// Coulomb with Ambrósio's dynamic correction coefficient c_d(|v|): F_t = −μ_k c_d N sign(v),
  /// c_d = 0 for |v| ≤ v₀, (|v| − v₀)/(v₁ − v₀) for v₀ < |v| < v₁, 1 for |v| ≥ v₁.
  /// Ambrósio (2003), "Impact of rigid and flexible multibody systems: deformation description
  /// and contact models".
  kAmbrosio,
  /// F_t = −N g(|v|) tanh(v/v_r), with the Stribeck curve g below.
  kTanh,
  /// LuGre bristle model in the normalised form (bristle forces proportional to N):
  ///   ż = v − σ₀ |v| z / g(|v|),   F_t = −(N (σ₀ z + σ₁ ż) + σ₂ v).
  /// Canudas de Wit, Olsson, Åström & Lischinsky (1995).
  kLuGre,
};

/// A friction force and its partial derivatives.
struct FrictionForce {
  double force = 0.0;             ///< F_t (N), on the slipping body, opposing v
  double dforce_dvelocity = 0.0;  ///< ∂F_t/∂v (N s/m)
  double dforce_dnormal = 0.0;    ///< ∂F_t/∂N (–)
};

/// One implicit-Euler step of the bristle state and the friction force at its end.
struct BristleStep {
  double deflection = 0.0;  ///< z at the end of the step (m)
  FrictionForce friction;   ///< F_t at the end of the step; ∂F_t/∂v includes ∂z/∂v
};

/// A friction law. Build it with the Make… factories below.
///
/// The Stribeck curve (kTanh, kLuGre) is g(s) = μ_k + (μ_s − μ_k) exp(−(s/v_s)²), s = |v|:
/// μ_s at rest, μ_k when sliding fast. Regularised laws (kAmbrosio, kTanh) cannot hold a body at
/// rest under a tangential load: they let it creep at the speed where their μ(v) balances it.
/// kLuGre sticks: under a load below μ_s N its bristles deflect to z = F/(σ₀ N) and the body
/// stops.
struct FrictionLaw {
  FrictionLawKind kind = FrictionLawKind::kTanh;
  double static_coefficient = 0.0;     ///< μ_s ≥ μ_k (kTanh, kLuGre)
  double kinetic_coefficient = 0.0;    ///< μ_k ≥ 0 (> 0 for kLuGre)
  double stribeck_speed = 1e-2;        ///< v_s (m/s), > 0 (kTanh, kLuGre)
  double ramp_start_speed = 1e-4;      ///< v₀ (m/s), ≥ 0 (kAmbrosio)
  double ramp_end_speed = 1e-3;        ///< v₁ (m/s), > v₀ (kAmbrosio)
  double regularization_speed = 1e-3;  ///< v_r (m/s), > 0 (kTanh)
  double bristle_stiffness = 1e4;      ///< σ₀ (1/m), > 0 (kLuGre)
  double bristle_damping = 0.0;        ///< σ₁ (s/m), ≥ 0 (kLuGre)
  double viscous_damping = 0.0;        ///< σ₂ (N s/m), ≥ 0 (kLuGre)

  /// g(s) (–) and dg/ds (s/m) at slip speed s = |v| ≥ 0.
  double CalcStribeck(double speed, double* dstribeck_dspeed = nullptr) const;

  /// F_t at slip velocity v (m/s) and normal force N (N) for kAmbrosio and kTanh; N ≤ 0 gives
  /// no force. Throws std::logic_error for kLuGre (use StepBristle).
  FrictionForce Evaluate(double velocity, double normal_force) const;

  /// kLuGre: advances z over a step h (s) by implicit Euler with the end-of-step velocity v,
  ///   z₁ = (z₀ + h v)/(1 + h σ₀ |v|/g(|v|)),   ż = (z₁ − z₀)/h,
  /// stable for the stiff bristle at any h, and returns z₁ and F_t(z₁, ż, v) with
  /// ∂F_t/∂v = −(N (σ₀ + σ₁/h) ∂z₁/∂v + σ₂), the derivative an implicit integrator needs.
  /// |v| is not differentiable at v = 0, where ∂|v|/∂v is taken as 0. The one-axis case of
  /// CalcTangentialBristleFriction (bristle_friction.hpp). Throws std::logic_error unless kind
  /// is kLuGre and h > 0.
  BristleStep StepBristle(double deflection, double velocity, double normal_force,
                          double step) const;
};

/// Ambrósio's law with μ (= μ_k = μ_s). Throws InputError unless 0 ≤ μ < ∞, 0 ≤ v₀ and
/// v₀ < v₁ < ∞ (m/s).
FrictionLaw MakeAmbrosioFriction(double coefficient, double ramp_start_speed,
                                 double ramp_end_speed);

/// The tanh law. Throws InputError unless 0 ≤ μ_k ≤ μ_s < ∞ and 0 < v_r, v_s < ∞ (m/s).
FrictionLaw MakeTanhFriction(double static_coefficient, double kinetic_coefficient,
                             double regularization_speed, double stribeck_speed);

/// The LuGre law. Throws InputError unless 0 < μ_k ≤ μ_s < ∞, 0 < v_s < ∞ (m/s),
/// 0 < σ₀ < ∞ (1/m), 0 ≤ σ₁ < ∞ (s/m), 0 ≤ σ₂ < ∞ (N s/m).
FrictionLaw MakeLuGreFriction(double static_coefficient, double kinetic_coefficient,
                              double stribeck_speed, double bristle_stiffness,
                              double bristle_damping, double viscous_damping);

/// Throws InputError, with a one-line message naming the parameter, unless `law` satisfies the
/// conditions listed on its factory.
void ValidateFrictionLaw(const FrictionLaw& law);

}  // namespace ancfnet
