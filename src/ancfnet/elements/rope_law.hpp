#pragma once
/// @file The smooth tension-only (rope) law of net threads: the elastic axial force per unit EA,
/// φ(ε), its derivatives and its energy density ψ(ε) = ∫ φ dε, with ψ ≥ 0 everywhere.

#include <cmath>
#include <utility>

namespace ancfnet {

/// φ(ε), φ′(ε), φ″(ε) and ψ(ε) of the smooth rope law at one strain.
struct RopeLawValue {
  double force = 0.0;      ///< φ: axial force / EA
  double slope = 0.0;      ///< φ′ = dφ/dε
  double curvature = 0.0;  ///< φ″
  double energy = 0.0;     ///< ψ: strain energy density / EA
};

/// The smooth maximum φ(ε) = (ε + r)/2, r = √(ε² + ε_s²), of ε and 0 (docs/theory.md, "Smooth
/// rope law"): within ε_s/2 of max(ε, 0) (at ε = 0), C^∞, φ′ = (1 + ε/r)/2 > 0, φ″ = ε_s²/(2r³).
/// Its energy density is measured from the least Green strain a material line can have,
/// ε = (|r′|² − 1)/2 ≥ −½ (a line shrunk to a point), so that ψ ≥ 0 for every configuration:
///   ψ(ε) = Ψ(ε) − Ψ(−½),   Ψ(ε) = ¼ [ε² + ε r + ε_s² ln((ε + r)/ε_s)],   Ψ′ = φ.
/// (Ψ alone, measured from ε = 0, is negative for every ε < 0.) ψ′ = φ exactly: the force is the
/// gradient of the energy that is accounted.
inline RopeLawValue CalcSmoothRopeLaw(double strain, double smoothing) {
  const double s2 = smoothing * smoothing;
  // r and ε + r, the latter as ε_s²/(r − ε) where ε < 0, which has no cancellation.
  const auto root_and_sum = [&](double eps) {
    const double r = std::sqrt(eps * eps + s2);
    return std::pair{r, eps >= 0.0 ? eps + r : s2 / (r - eps)};
  };
  // Ψ = ¼ [ε (ε + r) + ε_s² ln((ε + r)/ε_s)].
  const auto antiderivative = [&](double eps) {
    const double sum = root_and_sum(eps).second;
    return 0.25 * (eps * sum + s2 * std::log(sum / smoothing));
  };
  const auto [r, sum] = root_and_sum(strain);
  return {0.5 * sum, 0.5 * sum / r, 0.5 * s2 / (r * r * r),
          antiderivative(strain) - antiderivative(-0.5)};
}

}  // namespace ancfnet
