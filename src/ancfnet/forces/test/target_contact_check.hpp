#pragma once
/// @file Test helper: the generalised forces of target contact alone, and the relative error of
/// its assembled Jacobian (with the couplings of targets carried by bodies) against central
/// differences.

#include <vector>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"

namespace ancfnet::test {

/// Q of the contact forces alone at (q, v) (Workspace::internal_force).
inline VectorXd CalcTargetContactForces(const Model& model, const TargetContact& contact,
                                        const std::vector<ContactPairHistory>& history,
                                        const VectorXd& q, const VectorXd& v) {
  Workspace ws(model);
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  contact.AddForces(q, v, history, ws);
  return ws.internal_force;
}

/// |J − J_fd| / |J_fd| over all coordinates, J = ∂Q/∂q̇ (weights.damping = 1) or ∂Q/∂q
/// (weights.stiffness = 1) as AddJacobian assembles it.
inline double CalcTargetContactJacobianError(const Model& model, const TargetContact& contact,
                                             const std::vector<ContactPairHistory>& history,
                                             const VectorXd& q, const VectorXd& v,
                                             const IterationWeights& weights) {
  const DofMap all = DofMap::AllCoordinates(model);  // the matrix keeps a reference to it
  SystemMatrix matrix(model, all);
  std::vector<std::pair<Index, Index>> couplings;
  contact.FindBodyCouplings(q, v, 1e-3, matrix, &couplings);
  matrix.AddContactCouplings(couplings);
  matrix.SetZero();
  contact.AddJacobian(q, v, history, weights, &matrix);
  const MatrixXd analytic = MatrixXd(matrix.matrix());
  const MatrixXd fd = CalcCentralDifferenceJacobian(
      [&](const VectorXd& x, const VectorXd& x_dot) {
        return CalcTargetContactForces(model, contact, history, x, x_dot);
      },
      q, v, weights.stiffness != 0.0);
  return (analytic - fd).norm() / fd.norm();
}

}  // namespace ancfnet::test
