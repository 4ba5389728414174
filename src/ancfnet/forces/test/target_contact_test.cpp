// The contact forces with rigid targets: the Jacobians of the generalised forces against central
// differences, for a bent cable pressed into a sphere, a capsule and a faceted sphere (inspection
// spheres between the nodes, so the slopes take part) and for a point mass on a plane, with
// friction.

#include "ancfnet/forces/target_contact.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

const FrictionLaw kTanh = MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1);

Model MakePressedCable(ContactTarget target, const std::optional<FrictionLaw>& friction) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  ModelBuilder builder;
  builder.AddCable({.name = "rope",
                    .start = Vector3d(-0.2, 0.01, 0.299),
                    .end = Vector3d(0.2, -0.02, 0.2985),
                    .num_elements = 2,
                    .properties = MakeCableProperties(nylon, MakeCircleSection(0.004))});
  builder.AddPointMass("bead", 0.01, Vector3d(0.05, 0.02, 0.3009));
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.4);
  spec.friction = friction;
  spec.points_per_element = 5;
  spec.point_mass_radius = 0.002;
  spec.targets.push_back(target);
  builder.SetContact(spec);
  return builder.Build();
}

// `step` > 0: the LuGre bristles are stepped over it from the deflection `bristle`.
void ExpectJacobiansMatchFiniteDifferences(const Model& model, double step = 0.0,
                                           const Vector3d& bristle = Vector3d::Zero()) {
  TargetContact contact(model);
  contact.SetStepSize(step);
  VectorXd q = model.initial_positions();
  VectorXd v = VectorXd::Zero(model.num_dofs());
  for (Index i = 0; i < v.size(); ++i) v[i] = 0.01 * std::sin(1.7 * i + 0.3);
  std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)));
  for (std::size_t i = 0; i < history.size(); ++i) {
    history[i].speed = i % 2 ? 0.5 : -0.3;
    history[i].bristle = (i % 3 ? 1.0 : -0.5) * bristle;
  }
  const auto forces = [&](const VectorXd& x, const VectorXd& x_dot) {
    Workspace ws(model);
    ws.internal_force.setZero();
    ws.viscous_force.setZero();
    contact.AddForces(x, x_dot, history, ws);
    return VectorXd(ws.internal_force);
  };
  ASSERT_GE(contact.Summarize(q, v, history).active, 2);
  const DofMap all = DofMap::AllCoordinates(model);
  for (const IterationWeights weights :
       {IterationWeights{.mass = 0, .damping = 0, .stiffness = 1},
        IterationWeights{.mass = 0, .damping = 1, .stiffness = 0}}) {
    SystemMatrix matrix(model, all);
    matrix.SetZero();
    contact.AddJacobian(q, v, history, weights, &matrix);
    const MatrixXd analytic = MatrixXd(matrix.matrix());
    const MatrixXd fd = test::CalcCentralDifferenceJacobian(forces, q, v, weights.stiffness != 0.0);
    for (Index j = 0; j < model.num_dofs(); ++j)
      EXPECT_LT((analytic.col(j) - fd.col(j)).norm(), 2e-5 * analytic.norm() + 1e-9)
          << (weights.stiffness != 0.0 ? "stiffness" : "damping") << ", column " << j;
  }
}

TEST(TargetContact, JacobiansMatchFiniteDifferencesOnASphere) {
  ContactTarget sphere;
  sphere.kind = ContactTarget::Kind::kSphere;
  sphere.radius = 0.3;
  ExpectJacobiansMatchFiniteDifferences(MakePressedCable(sphere, std::nullopt));
  // With friction, the tangent plane turning with the position included.
  ExpectJacobiansMatchFiniteDifferences(MakePressedCable(sphere, kTanh));
}

TEST(TargetContact, JacobiansMatchFiniteDifferencesOnAPlane) {
  ContactTarget plane;
  plane.point = Vector3d(0, 0, 0.3);
  plane.normal = Vector3d(0.1, 0.0, 1.0).normalized();
  ExpectJacobiansMatchFiniteDifferences(MakePressedCable(plane, kTanh));
  // The LuGre law stepped over 1 ms from bristles deflected by up to 30 µm (off the tangent
  // plane too: they are re-projected), with bristle damping and viscous friction.
  ExpectJacobiansMatchFiniteDifferences(
      MakePressedCable(plane, MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1)), 1e-3,
      Vector3d(3e-5, -1e-5, 5e-6));
}

TEST(TargetContact, JacobiansMatchFiniteDifferencesOnACapsuleAndAMesh) {
  ContactTarget capsule;
  capsule.kind = ContactTarget::Kind::kCapsule;
  capsule.normal = Vector3d::UnitY();
  capsule.half_length = 0.1;
  capsule.radius = 0.3;
  ExpectJacobiansMatchFiniteDifferences(MakePressedCable(capsule, std::nullopt));
  ContactTarget mesh;
  mesh.kind = ContactTarget::Kind::kMesh;
  mesh.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.3, 4));
  ExpectJacobiansMatchFiniteDifferences(MakePressedCable(mesh, std::nullopt));
}

}  // namespace
}  // namespace ancfnet
