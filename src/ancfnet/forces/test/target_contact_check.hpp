#pragma once
/// @file Test helper: the generalised forces of target contact alone, and the relative error of
/// its assembled Jacobian (with the couplings of targets carried by bodies) against central
/// differences.

#include <optional>
#include <vector>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet::test {

/// The contact tests' rope: a 4 mm nylon cable "rope" of two elements from a to b.
inline void AddTestRope(const Vector3d& a, const Vector3d& b, ModelBuilder* builder) {
  const Material nylon{.youngs_modulus = 3e9, .density = 1140};
  builder->AddCable({.name = "rope",
                     .start = a,
                     .end = b,
                     .num_elements = 2,
                     .properties = MakeCableProperties(nylon, MakeCircleSection(0.004))});
}

/// The contact tests' law: Carvalho–Martins, k = 10⁶, e = 0.4, 5 inspection spheres per element,
/// with `friction` (none: frictionless) and no targets yet.
inline ContactSpec MakeTestContactSpec(const std::optional<FrictionLaw>& friction) {
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.4);
  spec.friction = friction;
  spec.points_per_element = 5;
  return spec;
}

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
