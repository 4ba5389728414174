// Capsule chains of a cable against rigid targets (ContactSpec::TargetGeometry::kCapsules): the
// generalised force is minus the gradient of the contact energy (central differences; exact by
// the envelope theorem though t* moves) for a cable crossing a sphere, a box edge and a faceted
// sphere, and both Jacobians (with the motion of t*) match central differences; the records
// carry the ξ of the deepest point; a target carried by a moving body feels the reaction.

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/contact/distance/point_segment.hpp"
#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/forces/test/target_contact_check.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

// A straight cable of 2 elements, 3 capsules each (radius 2 mm), from a to b; the node between
// the elements lies at x = −0.03, so that the deepest point at x ≈ 0 is inside a capsule.
Model MakeCrossingCable(ContactTarget target, const Vector3d& a, const Vector3d& b,
                        const std::string& body = "") {
  ModelBuilder builder;
  if (!body.empty())
    builder.AddRigidBody({.name = body,
                          .mass = 5.0,
                          .inertia = Vector3d(0.2, 0.3, 0.4).asDiagonal(),
                          .velocity = Vector3d(0.1, -0.2, 0.05),
                          .angular_velocity = Vector3d(0.3, -0.5, 0.7)});
  test::AddTestRope(a, b, &builder);
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.4);
  spec.target_geometry = ContactSpec::TargetGeometry::kCapsules;
  spec.capsules_per_element = 3;
  target.body_name = body;
  spec.targets.push_back(target);
  builder.SetContact(spec);
  return builder.Build();
}

const Vector3d kStart(-0.23, 0.01, 0.299), kEnd(0.17, -0.02, 0.2985);

ContactTarget Sphere() {
  ContactTarget sphere;
  sphere.kind = ContactTarget::Kind::kSphere;
  sphere.radius = 0.3;
  return sphere;
}

// Contact energy E(q) and the generalised force Q = −ws.internal_force at v = 0 (no damping, no
// friction): Q = −∂E/∂q.
void ExpectForceIsMinusTheEnergyGradient(const Model& model, int min_active) {
  const TargetContact contact(model);
  const VectorXd q = model.initial_positions();
  const VectorXd v = VectorXd::Zero(model.num_dofs());
  const std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                                ContactPairHistory{.speed = 0.5});
  Workspace ws(model);
  const auto evaluate = [&](const VectorXd& x) {
    ws.internal_force.setZero();
    ws.viscous_force.setZero();
    contact.AddForces(x, v, history, ws);
    return ws.contact_energy;
  };
  ASSERT_GE(contact.Summarize(q, v, history).active, min_active);
  evaluate(q);
  const VectorXd gradient = ws.internal_force;  // = −Q = ∂E/∂q
  VectorXd fd(q.size());
  const double h = 1e-7;
  for (Index j = 0; j < q.size(); ++j) {
    VectorXd plus = q, minus = q;
    plus[j] += h;
    minus[j] -= h;
    fd[j] = (evaluate(plus) - evaluate(minus)) / (2 * h);
  }
  const double error = (gradient - fd).norm() / gradient.norm();
  std::printf("capsules: |Q + dE/dq| / |Q| = %.2e (|Q| = %.3e)\n", error, gradient.norm());
  EXPECT_LT(error, 1e-6);
}

// ∂Q/∂q̇ and ∂Q/∂q against central differences, with the body couplings of a carried target.
void ExpectJacobiansMatch(const Model& model) {
  const TargetContact contact(model);
  const State state = MakeInitialState(model);
  VectorXd v = state.v;
  for (Index i = 0; i < 6 * model.num_nodes(); ++i) v[i] += 0.01 * std::sin(1.7 * i + 0.3);
  const std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                                ContactPairHistory{.speed = -0.2});
  for (const IterationWeights weights :
       {IterationWeights{.mass = 0, .damping = 1, .stiffness = 0},
        IterationWeights{.mass = 0, .damping = 0, .stiffness = 1}}) {
    const double error =
        test::CalcTargetContactJacobianError(model, contact, history, state.q, v, weights);
    std::printf("capsules: %s Jacobian relative error %.2e\n",
                weights.stiffness != 0.0 ? "stiffness" : "damping", error);
    EXPECT_LT(error, 1e-6);
  }
}

TEST(TargetCapsuleContact, ForceIsMinusTheEnergyGradientAcrossASphere) {
  const Model model = MakeCrossingCable(Sphere(), kStart, kEnd);
  ExpectForceIsMinusTheEnergyGradient(model, 2);
  ExpectJacobiansMatch(model);
}

TEST(TargetCapsuleContact, ForceIsMinusTheEnergyGradientAcrossABoxEdge) {
  // The edge x = 0, z = 0.3 along y of a box below z = 0.3 and behind x = 0; the cable passes
  // 1 mm above the edge, sloping down by 1 in 40.
  ContactTarget box;
  box.kind = ContactTarget::Kind::kBox;
  box.point = Vector3d(-0.5, 0.0, -0.2);
  box.half_extents = Vector3d(0.5, 0.5, 0.5);
  const Model model = MakeCrossingCable(box, Vector3d(-0.23, 0.01, 0.301 + 0.025 * 0.23),
                                        Vector3d(0.17, -0.02, 0.301 - 0.025 * 0.17));
  ExpectForceIsMinusTheEnergyGradient(model, 2);
  ExpectJacobiansMatch(model);
}

TEST(TargetCapsuleContact, ForceIsMinusTheEnergyGradientAcrossAMesh) {
  ContactTarget mesh;
  mesh.kind = ContactTarget::Kind::kMesh;
  mesh.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.3, 4));
  // The axis outside the faceted surface (δ < r), where its signed distance is C¹; inside, it is
  // the maximum of the faces' planes, and a minimum along the axis on a kink between two faces
  // has no gradient (theory.md, "Capsule chains against rigid targets").
  const Vector3d up(0.0, 0.0, 0.0015);
  const Model model = MakeCrossingCable(mesh, kStart + up, kEnd + up);
  ExpectForceIsMinusTheEnergyGradient(model, 1);
  ExpectJacobiansMatch(model);
}

TEST(TargetCapsuleContact, RecordsCarryTheDeepestPoint) {
  // The straight cable's chords are the cable: the deepest point is the foot of the
  // perpendicular from the sphere's centre, at x ≈ 0 on the second element (x from −0.03).
  const Model model = MakeCrossingCable(Sphere(), kStart, kEnd);
  const TargetContact contact(model);
  const std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                                ContactPairHistory{.speed = 0.5});
  std::vector<ContactPoint> records;
  const VectorXd v = VectorXd::Zero(model.num_dofs());
  contact.CollectContacts(model.initial_positions(), v, history, &records);
  const PointSegmentDistance foot = CalcPointSegmentDistance(Vector3d::Zero(), kStart, kEnd);
  const double xi = 2.0 * foot.t - 1.0;  // on the second element
  bool found = false;
  for (const ContactPoint& r : records) {
    if (r.element != 1 || r.xi <= 0.0 || r.xi >= 1.0 / 3.0) continue;
    found = true;
    EXPECT_NEAR(r.xi, xi, 1e-9);
    EXPECT_NEAR(r.penetration, 0.002 - (foot.distance - 0.3), 1e-12);
  }
  EXPECT_TRUE(found);
}

TEST(TargetCapsuleContact, ABodyTargetFeelsTheReaction) {
  const Model model = MakeCrossingCable(Sphere(), kStart, kEnd, "ball");
  const TargetContact contact(model);
  const State state = MakeInitialState(model);
  const std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                                ContactPairHistory{.speed = -0.2});
  Workspace ws(model);
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  contact.AddForces(state.q, state.v, history, ws);
  Vector3d on_cable = Vector3d::Zero();
  for (Index node = 0; node < model.num_nodes(); ++node)
    on_cable += ws.internal_force.segment<3>(model.NodePositionDof(node));
  const RigidBody& body = model.rigid_bodies()[0];
  ASSERT_GT(on_cable.norm(), 1.0);
  EXPECT_LT((on_cable + ws.internal_force.segment<3>(body.position_dof())).norm(),
            1e-12 * on_cable.norm());
  ExpectJacobiansMatch(model);
}

}  // namespace
}  // namespace ancfnet
