#pragma once
/// @file The damping matrices of a model's Rayleigh and modal damping (model/damping_spec.hpp),
/// made once from the reference configuration and applied as forces Q = C q̇ in the dynamic
/// solvers (docs/theory.md, "Rayleigh and modal damping").

#include <vector>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

class DampingModel {
 public:
  /// Rayleigh: per element α M_e + β K_e(q₀) (a beam element's, its centre line contributing
  /// nothing) and α m per point mass. Modal: the lowest
  /// elastic modes Φ of the reference configuration and B = M Φ, C = B diag(2 ζ_i ω_i) Bᵀ.
  /// Throws SolverError when the modes for modal damping cannot be found.
  explicit DampingModel(const Model& model);

  bool empty() const { return element_rayleigh_.empty() && modal_basis_.cols() == 0; }
  /// ws.internal_force and ws.viscous_force += C v (all coordinates).
  void AddForces(const VectorXd& v, Workspace& ws) const;
  /// matrix += weight · C_Rayleigh. The modal part is dense (rank k) and is left out of
  /// iteration matrices: Newton then converges linearly on it (docs/theory.md).
  void AddRayleighJacobian(double weight, SystemMatrix* matrix) const;
  /// Φ_sᵀ C_modal Φ_s for shapes Φ_s over all coordinates (k_s × k_s).
  MatrixXd ProjectModal(const MatrixXd& shapes) const;

 private:
  const Model& model_;
  std::vector<Matrix12d> element_rayleigh_;  // empty without Rayleigh damping
  std::vector<Matrix24d> beam_rayleigh_;     // per beam element; empty without Rayleigh damping
  double alpha_ = 0.0;
  MatrixXd modal_basis_;         // B = M Φ (num_dofs × k); no columns without modal damping
  VectorXd modal_coefficients_;  // 2 ζ_i ω_i (1/s)
  mutable VectorXd modal_coordinates_;  // scratch, sized once
  mutable VectorXd modal_force_;
};

}  // namespace ancfnet
