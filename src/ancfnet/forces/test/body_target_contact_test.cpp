// Contact with a target carried by a free, moving, spinning rigid body: the generalised forces
// on the cable and on the body, and their Jacobians with respect to every coordinate (the
// body's x and ψ included) against central differences; which probes the iteration matrix
// couples with the body (FindBodyCouplings) as the body spins under a rope at rest.

#include <gtest/gtest.h>

#include <optional>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/forces/test/target_contact_check.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

Model MakeCableOnATumblingBox(const std::optional<FrictionLaw>& friction) {
  ModelBuilder builder;
  const Matrix3d turn = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  builder.AddRigidBody({.name = "target",
                        .mass = 5.0,
                        .inertia = Vector3d(0.2, 0.3, 0.4).asDiagonal(),
                        .position = Vector3d(0.01, -0.02, 0.03),
                        .orientation = turn,
                        .velocity = Vector3d(0.1, -0.2, 0.05),
                        .angular_velocity = Vector3d(0.3, -0.5, 0.7)});
  // A cable across the box's top face (z_B = 0.1), 1.5 mm into it at its middle.
  const Vector3d a =
      Vector3d(0.01, -0.02, 0.03) + turn * Vector3d(-0.2, 0.01, 0.1 + 0.002 - 0.0015);
  const Vector3d b =
      Vector3d(0.01, -0.02, 0.03) + turn * Vector3d(0.2, -0.02, 0.1 + 0.002 - 0.0012);
  test::AddTestRope(a, b, &builder);
  ContactSpec spec = test::MakeTestContactSpec(friction);
  ContactTarget box;
  box.kind = ContactTarget::Kind::kBox;
  box.half_extents = Vector3d(0.3, 0.3, 0.1);
  box.body_name = "target";
  spec.targets.push_back(box);
  builder.SetContact(spec);
  return builder.Build();
}

// `step` > 0: the LuGre bristles are stepped over it from `bristle_B`, in the body's frame.
void ExpectJacobiansMatch(const Model& model, double tolerance, double step = 0.0,
                          const Vector3d& bristle_B = Vector3d::Zero()) {
  TargetContact contact(model);
  contact.SetStepSize(step);
  const State state = MakeInitialState(model);
  VectorXd v = state.v;
  for (Index i = 0; i < 6 * model.num_nodes(); ++i) v[i] += 0.01 * std::sin(1.7 * i + 0.3);
  std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                          {.speed = -0.2, .bristle = bristle_B});
  ASSERT_GE(contact.Summarize(state.q, v, history).active, 3);
  // Action and reaction: the body's force balances the cable's.
  const VectorXd f = test::CalcTargetContactForces(model, contact, history, state.q, v);
  const RigidBody& body = model.rigid_bodies()[0];
  Vector3d on_cable = Vector3d::Zero();
  for (Index node = 0; node < model.num_nodes(); ++node)
    on_cable += f.segment<3>(model.NodePositionDof(node));
  EXPECT_LT((on_cable + f.segment<3>(body.position_dof())).norm(), 1e-12 * on_cable.norm());
  for (const IterationWeights weights :
       {IterationWeights{.mass = 0, .damping = 0, .stiffness = 1},
        IterationWeights{.mass = 0, .damping = 1, .stiffness = 0}}) {
    const double error =
        test::CalcTargetContactJacobianError(model, contact, history, state.q, v, weights);
    std::printf("contact with a body, %s Jacobian: relative error %.2e\n",
                weights.stiffness != 0.0 ? "stiffness" : "damping", error);
    EXPECT_LT(error, tolerance);
  }
}

TEST(BodyTargetContact, JacobiansMatchFiniteDifferences) {
  // Complete: the change of G and of the body's moment arm with the rotation included.
  ExpectJacobiansMatch(MakeCableOnATumblingBox(std::nullopt), 1e-6);
  ExpectJacobiansMatch(MakeCableOnATumblingBox(MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1)), 1e-6);
  // The LuGre law, its bristles turned with the body (z_W = R_WB z_B).
  ExpectJacobiansMatch(MakeCableOnATumblingBox(MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1)),
                       1e-6, 1e-3, Vector3d(2e-5, -1e-5, 0.0));
}

// A rope at rest 0.15 m over the centre of a ball of radius 0.1 m spinning about z at ω: a probe
// ρ from the axis is d = √(ρ² + 0.15²) − 0.1 from the ball and coupled with the body where
// d < 1.5 r + 2 h ω ρ (r = 2 mm, h = 1 ms): none at ω = 100/s; at 400/s those with ρ ≳ 0.08 m;
// more at 1000/s. The ball is its own bounding ball, so the cull before the distance query is
// what decides here, and it must keep the probes the spinning surface reaches.
int CountBodyCouplings(double spin) {
  ModelBuilder builder;
  builder.AddRigidBody({.name = "target",
                        .mass = 5.0,
                        .inertia = Vector3d(0.2, 0.3, 0.4).asDiagonal(),
                        .angular_velocity = Vector3d(0.0, 0.0, spin)});
  test::AddTestRope(Vector3d(-0.2, 0.0, 0.15), Vector3d(0.2, 0.0, 0.15), &builder);
  ContactSpec spec = test::MakeTestContactSpec(std::nullopt);
  ContactTarget ball;
  ball.kind = ContactTarget::Kind::kSphere;
  ball.radius = 0.1;
  ball.body_name = "target";
  spec.targets.push_back(ball);
  builder.SetContact(spec);
  const Model model = builder.Build();
  const State state = MakeInitialState(model);
  const DofMap all = DofMap::AllCoordinates(model);
  const SystemMatrix matrix(model, all);
  std::vector<std::pair<Index, Index>> couplings;
  TargetContact(model).FindBodyCouplings(state.q, state.v, 1e-3, matrix, &couplings);
  return static_cast<int>(couplings.size());
}

TEST(BodyTargetContact, CouplesTheProbesTheSpinningFaceCanReachWithinTheStep) {
  EXPECT_EQ(CountBodyCouplings(0.0), 0);
  EXPECT_EQ(CountBodyCouplings(100.0), 0);
  const int outer = CountBodyCouplings(400.0);
  EXPECT_GT(outer, 0);
  EXPECT_LT(outer, CountBodyCouplings(1000.0));
}

}  // namespace
}  // namespace ancfnet
