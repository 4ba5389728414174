#pragma once
/// @file Damping models of a whole model, beyond the material's Kelvin–Voigt damping: Rayleigh
/// damping C = α M + β K₀ and the generic ("modal") damping matrix built from measured modal
/// damping ratios, C = M Φ diag(2 ζ_i ω_i) Φᵀ M (Adhikari 2006; the seed paper's generic damping).
/// The matrices themselves are made by solvers/damping_model.hpp.

#include <utility>
#include <vector>

namespace ancfnet {

/// C = α M + β K₀ (K₀ the cable elements' tangent stiffness at the reference configuration), so
/// that a mode of frequency ω gets ζ = α/(2ω) + β ω/2.
struct RayleighDamping {
  double alpha = 0.0;  ///< 1/s, ≥ 0
  double beta = 0.0;   ///< s, ≥ 0
};

/// α and β that give ζ₁ at f₁ and ζ₂ at f₂ (Hz, f₁ ≠ f₂): from ζ = α/(2ω) + β ω/2,
/// α = 2 ω₁ ω₂ (ζ₁ ω₂ − ζ₂ ω₁)/(ω₂² − ω₁²), β = 2 (ζ₂ ω₂ − ζ₁ ω₁)/(ω₂² − ω₁²). Throws InputError
/// when the frequencies are not positive and different, or when α or β would be negative.
RayleighDamping FitRayleighDamping(double f1, double zeta1, double f2, double zeta2);

/// The lowest `num_modes` elastic modes of the reference configuration each get a damping ratio:
/// ratios[i] for mode i, or, when `ratios` is empty, ζ(f) interpolated linearly in the measured
/// table of (frequency Hz, ratio) pairs (held constant beyond its ends). Rigid modes and modes
/// beyond num_modes get no damping from this matrix.
struct ModalDamping {
  int num_modes = 0;  ///< 0: no modal damping
  std::vector<double> ratios;
  std::vector<std::pair<double, double>> table;
  /// ζ of a mode of index i (0-based) and frequency f (Hz).
  double Ratio(int i, double f) const;
};

struct DampingSpec {
  RayleighDamping rayleigh;
  ModalDamping modal;
  bool empty() const {
    return rayleigh.alpha == 0.0 && rayleigh.beta == 0.0 && modal.num_modes == 0;
  }
};

}  // namespace ancfnet
