#pragma once
/// @file Normal contact force laws: the compressive force F_n (N) between two touching bodies
/// as a function of the penetration δ ≥ 0 (m), its rate δ̇ (m/s, positive while approaching)
/// and the normal approach speed v₀ (m/s) stored when the pair first touched. The dissipative
/// laws share the form
///   F_n = k δⁿ (1 + χ̂(e) δ̇/v₀),
/// and differ only in the hysteresis damping factor χ̂ they derive from the coefficient of
/// restitution e. A law never pulls: F_n = max(·, 0). The derivation of the restitution each
/// law achieves is in docs/theory.md, "Contact force laws"; the measured values in
/// docs/validation.md. A law is a plain value built once (by the Make… factories, which
/// validate it) and evaluated without allocating.

namespace ancfnet {

/// The closed list of normal contact laws.
enum class NormalLawKind {
  kLinear,              ///< F = k δ + c δ̇ (Kelvin–Voigt spring-dashpot)
  kHertz,               ///< F = k δⁿ (elastic, Hertz 1882; n = 3/2 for spheres)
  kHuntCrossley,        ///< χ̂ = 3(1 − e)/2. Hunt & Crossley (1975)
  kLankaraniNikravesh,  ///< χ̂ = 3(1 − e²)/4. Lankarani & Nikravesh (1990)
  kFlores,              ///< χ̂ = 8(1 − e)/(5e). Flores, Machado, Silva & Martins (2011)
  kGonthier,            ///< χ̂ = (1 − e²)/e. Gonthier, McPhee, Lange & Piedbœuf (2004)
  kCarvalhoMartins,     ///< χ̂ = 3(1 − e)(11 − e)/(2(1 + 9e)). Carvalho & Martins (2019)
};

/// The normal force and its partial derivatives (for the Newton iteration matrix).
struct NormalForce {
  double force = 0.0;              ///< F_n (N), ≥ 0, pushing the bodies apart
  double dforce_ddelta = 0.0;      ///< ∂F_n/∂δ (N/m)
  double dforce_ddelta_dot = 0.0;  ///< ∂F_n/∂δ̇ (N s/m)
  double elastic_force = 0.0;      ///< k δⁿ (N), the conservative part (0 for δ ≤ 0)
};

/// A normal contact law. Build it with the Make… factories below.
///
/// For δ ≤ 0 the bodies are apart and every output is 0. Otherwise
///   kLinear:      F = max(k δ + c δ̇, 0),
///   kHertz:       F = k δⁿ,
///   dissipative:  F = max(k δⁿ (1 + χ̂ δ̇/v̄₀), 0),   v̄₀ = max(v₀, v_min),
/// where the floor v_min keeps the damping bounded for pairs that touch at rest. Where the max
/// clips, F and both derivatives are 0 (no adhesion). In a free impact of a law of this form
/// the clip never acts (docs/theory.md), and the achieved restitution e* solves
///   χ̂ (1 + e*) = ln[(1 + χ̂)/(1 − χ̂ e*)]    (CalcRestitutionForHysteresisFactor),
/// whatever k, n, the mass and v₀.
struct NormalLaw {
  NormalLawKind kind = NormalLawKind::kHertz;
  double stiffness = 0.0;            ///< k (N/mⁿ), > 0
  double exponent = 1.5;             ///< n, > 0 (1 for kLinear)
  double damping = 0.0;              ///< c (N s/m), ≥ 0: kLinear only
  double restitution = 1.0;          ///< e, 0 < e ≤ 1: dissipative kinds only
  double min_approach_speed = 1e-3;  ///< v_min (m/s), > 0: dissipative kinds only

  /// χ̂ of this law (0 for kLinear and kHertz).
  double hysteresis_factor() const;

  /// F_n and its derivatives at penetration δ (m), rate δ̇ (m/s, > 0 approaching) and stored
  /// approach speed v₀ (m/s; ignored by kLinear and kHertz).
  NormalForce Evaluate(double delta, double delta_dot, double approach_speed) const;

  /// Energy stored in the elastic part, ∫₀^δ k sⁿ ds = k δⁿ⁺¹/(n + 1) (J); 0 for δ ≤ 0.
  double CalcElasticEnergy(double delta) const;
};

/// F = k δ + c δ̇. Throws InputError unless 0 < k < ∞ (N/m) and 0 ≤ c < ∞ (N s/m).
NormalLaw MakeLinearContactLaw(double stiffness, double damping);

/// F = k δⁿ. Throws InputError unless 0 < k < ∞ (N/mⁿ) and 0 < n < ∞. For two elastic spheres
/// k = (4/3) E* √R* and n = 3/2 (Johnson 1985, ch. 4).
NormalLaw MakeHertzContactLaw(double stiffness, double exponent = 1.5);

/// F = k δⁿ (1 + χ̂(e) δ̇/v̄₀) with χ̂ of `kind` (one of the dissipative kinds). Throws InputError
/// unless `kind` is dissipative, 0 < k < ∞, 0 < n < ∞, 0 < e ≤ 1 and 0 < v_min < ∞ (m/s).
NormalLaw MakeDissipativeContactLaw(NormalLawKind kind, double stiffness, double restitution,
                                    double exponent = 1.5, double min_approach_speed = 1e-3);

/// The hysteresis damping factor χ̂(e) of a dissipative kind (0 for kLinear and kHertz):
///   Hunt & Crossley (1975):        3(1 − e)/2
///   Lankarani & Nikravesh (1990):  3(1 − e²)/4
///   Flores et al. (2011):          8(1 − e)/(5e)
///   Gonthier et al. (2004):        (1 − e²)/e
///   Carvalho & Martins (2019):     3(1 − e)(11 − e)/(2(1 + 9e))
/// Precondition: 0 < e ≤ 1.
double CalcHysteresisFactor(NormalLawKind kind, double restitution);

/// The restitution e* ∈ (0, 1] that a law F = k δⁿ (1 + χ̂ δ̇/v₀) achieves in a free impact:
/// the root of χ̂ (1 + e*) = ln[(1 + χ̂)/(1 − χ̂ e*)] in (0, min(1, 1/χ̂)) (1 for χ̂ = 0).
/// Throws InputError unless 0 ≤ χ̂ < ∞.
double CalcRestitutionForHysteresisFactor(double hysteresis_factor);

/// Throws InputError, with a one-line message naming the parameter, unless `law` satisfies the
/// conditions listed on the factories.
void ValidateNormalLaw(const NormalLaw& law);

}  // namespace ancfnet
