#pragma once
/// @file Modal analysis: natural frequencies and mass-normalised mode shapes of the model
/// linearised about a configuration (the reference one, or a static equilibrium such as a taut
/// net), with the fixed coordinates eliminated, and the damping ratio each mode gets from the
/// model's damping. Lowest modes by shift-invert Lanczos (Spectra) on K φ = ω² M φ.

#include <string>
#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

struct ModalSettings {
  int num_modes = 6;  ///< k ≥ 1, fewer than the unknowns
  /// Shift σ (rad²/s²) of the spectral transformation (K − σ M)⁻¹ M; the modes returned are those
  /// with ω² nearest σ. Any σ < 0 gives the lowest modes, rigid ones (ω = 0) included, and keeps
  /// K − σ M positive definite for free-floating systems. 0: automatic (a negative shift below
  /// the lowest elastic eigenvalue, from a first pass).
  double shift = 0.0;
  double tolerance = 1e-10;  ///< relative accuracy of the eigenvalues (Spectra)
};

struct ModalResult {
  bool converged = false;
  std::string message;  ///< why not
  /// Circular frequencies ω_i (rad/s), ascending; modes with |ω²| below 10⁻⁹ of max K_ii/max M_ii
  /// (the round-off of K) are rigid and reported as exactly 0.
  VectorXd omega;
  VectorXd frequency_hz;  ///< f_i = ω_i / 2π
  /// Damping ratio of each mode from the complex eigenvalues s = −ζω ± iω√(1 − ζ²) of the damped
  /// linearised system projected on the k modes (exact for Rayleigh and modal damping); 0
  /// without damping; NaN for a rigid mode.
  VectorXd damping_ratio;
  /// Mode shapes over all coordinates (num_dofs × k), mass-normalised φᵀ M φ = 1, zero on the
  /// fixed coordinates.
  MatrixXd shapes;
  std::vector<bool> rigid;
};

/// The undamped modes alone: ω² ascending (rigid ones 0), M-orthonormal shapes over all
/// coordinates (zero on the fixed ones), rigid flags. Used by CalcModes and by the modal damping
/// matrix (solvers/damping_model.hpp).
struct UndampedModes {
  bool converged = false;
  std::string message;
  VectorXd omega_squared;
  MatrixXd shapes;
  std::vector<bool> rigid;
};
UndampedModes CalcUndampedModes(const Model& model, const VectorXd& q,
                                const ModalSettings& settings);

/// Linearises the model about configuration `q` at rest: K = ∂(Q_int − Q_ext)/∂q (symmetrised),
/// C = ∂Q_int/∂q̇, M the mass matrix, over the free coordinates, and returns the lowest modes.
/// Throws InputError for k out of range. A failed eigen solve is reported in the result.
ModalResult CalcModes(const Model& model, const VectorXd& q, const ModalSettings& settings);

}  // namespace ancfnet
