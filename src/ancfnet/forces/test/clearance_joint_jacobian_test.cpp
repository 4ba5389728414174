// The generalised forces of clearance joints between every kind of anchor (ground, free spinning
// rigid bodies, a point mass, ANCF cable points whose slope carries the friction moment), and
// their Jacobians ∂Q/∂q and ∂Q/∂q̇ against central differences; with the LuGre law, a nonzero
// stored bristle stepped over h (turning with a body bearing, docs/theory.md "Clearance joints").

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"
#include "ancfnet/forces/test/spinning_body.hpp"
#include "ancfnet/forces/test/target_contact_check.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

constexpr double kClearance = 1e-3;
constexpr double kJournalRadius = 0.01;
const Vector3d kRopeEnd(0.3, 0.1, 0.05);
// The bearing's centre on the rope (s = 0.3) and the journal's, 50 µm into the bearing's wall
// (a revolute joint's journal also 4 mm along the axis, which does not count).
const Vector3d kBearingCenter = 0.3 * kRopeEnd;
Vector3d JournalCenter(ClearanceJoint::Type type) {
  const Vector3d axial =
      type == ClearanceJoint::Type::kRevolute ? Vector3d(0, 0, 4e-3) : Vector3d::Zero();
  return kBearingCenter + (kClearance + 5e-5) * Vector3d(0.6, 0.8, 0.0) + axial;
}

using Kind = JointAnchor::Kind;

// Where a body carrying a side has its centre of mass, from that side's centre.
const Vector3d kBodyOffset(0.02, -0.01, 0.03);

// The journal and bearing of a test joint: which kinds, and the joint's type and friction.
struct Case {
  const char* label;
  Kind journal;
  Kind bearing;
  ClearanceJoint::Type type;
  std::optional<FrictionLaw> friction;
};

Model MakeJointModel(const Case& c, bool journal_on_point_mass) {
  ModelBuilder builder;
  test::AddTestRope(Vector3d::Zero(), kRopeEnd, &builder);
  builder.SetInitialVelocity("rope", Vector3d(0.01, 0.02, -0.01), Vector3d(1.0, -2.0, 3.0));
  ClearanceJointSpec spec{
      .name = "pin",
      .type = c.type,
      .clearance = kClearance,
      .journal_radius = kJournalRadius,
      .axis = Vector3d(0, 0, 2),
      .normal = MakeDissipativeContactLaw(NormalLawKind::kLankaraniNikravesh, 1e8, 0.7),
      .friction = c.friction};
  // The journal: a body, a point mass or the ground.
  const Vector3d journal_center = JournalCenter(c.type);
  if (c.journal == Kind::kBody) {
    test::AddSpinningBody("journal", journal_center + kBodyOffset, 0.4, &builder);
    spec.journal = {.kind = Kind::kBody, .name = "journal", .position = journal_center};
  } else if (c.journal == Kind::kPoint && journal_on_point_mass) {
    builder.AddPointMass("ball", 0.1, journal_center, Vector3d(0.03, -0.04, 0.02));
    spec.journal = {.kind = Kind::kPoint, .name = "ball"};
  } else {
    spec.journal = {.kind = Kind::kGround, .position = journal_center};
  }
  // The bearing: the rope's point at s = 0.3, or a body.
  if (c.bearing == Kind::kBody) {
    test::AddSpinningBody("bearing", kBearingCenter + kBodyOffset, 0.4, &builder);
    spec.bearing = {.kind = Kind::kBody, .name = "bearing", .position = kBearingCenter};
  } else {
    spec.bearing = {.kind = Kind::kPoint, .name = "rope", .s = 0.3};
  }
  builder.AddClearanceJoint(spec);
  return builder.Build();
}

// The joint's history and step: impact speed 0.2 m/s, a LuGre bristle z₀ (in the bearing's
// frame, at σ₀ = 10⁴/m about a tenth of μ_s) advanced over h = 1 ms (other laws ignore both).
Workspace MakeJointWorkspace(const Model& model) {
  Workspace ws(model);
  ws.joint_history[0].speed = 0.2;
  ws.joint_history[0].bristle = Vector3d(2e-6, -1e-6, 3e-6);
  ws.joint_step = 1e-3;
  return ws;
}

VectorXd CalcJointForces(const Model& model, const VectorXd& q, const VectorXd& v) {
  Workspace ws = MakeJointWorkspace(model);
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  AddClearanceJointForces(model, q, v, ws);
  return ws.internal_force;
}

// ‖analytic − FD‖/‖FD‖ over all columns, or over the `count` columns from `first` (3 from a body
// bearing's ψ: the bristle's turning with the body is small beside the normal law's stiffness).
double CalcJacobianError(const Model& model, const VectorXd& q, const VectorXd& v,
                         const IterationWeights& weights, Index first = 0, Index count = -1) {
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix matrix(model, all);
  const Workspace ws = MakeJointWorkspace(model);
  matrix.SetZero();
  AddClearanceJointJacobians(model, q, v, weights, ws, &matrix);
  const MatrixXd analytic = MatrixXd(matrix.matrix());
  const MatrixXd fd = test::CalcCentralDifferenceJacobian(
      [&](const VectorXd& x, const VectorXd& x_dot) { return CalcJointForces(model, x, x_dot); }, q,
      v, weights.stiffness != 0.0);
  if (count < 0) count = fd.cols() - first;
  return (analytic - fd).middleCols(first, count).norm() / fd.middleCols(first, count).norm();
}

void ExpectJacobiansMatch(const Case& c, bool journal_on_point_mass = false) {
  const Model model = MakeJointModel(c, journal_on_point_mass);
  const State state = MakeInitialState(model);
  const Workspace ws = MakeJointWorkspace(model);
  const ClearanceJointState s = CalcClearanceJointState(
      model, 0, state.q, state.v, ws.body_rotation, ws.joint_history[0], false, ws.joint_step);
  ASSERT_TRUE(s.contact.touching) << c.label;
  EXPECT_NEAR(s.contact.penetration, 5e-5, 1e-12) << c.label;
  if (c.friction) {
    EXPECT_GT(s.contact.friction.norm(), 1e-3 * s.contact.normal_force) << c.label;
  }
  if (c.friction && c.friction->kind == FrictionLawKind::kLuGre) {
    // The bristle is stepped (it moved from z₀) and holds a part of the friction force.
    EXPECT_GT((s.contact.bristle - ws.joint_history[0].bristle).norm(), 1e-9) << c.label;
    EXPECT_GT(s.contact.bristle.norm(), 1e-7) << c.label;
  }
  for (const IterationWeights weights :
       {IterationWeights{.mass = 0, .damping = 0, .stiffness = 1},
        IterationWeights{.mass = 0, .damping = 1, .stiffness = 0}}) {
    const double error = CalcJacobianError(model, state.q, state.v, weights);
    std::printf("%s, %s Jacobian: relative error %.2e\n", c.label,
                weights.stiffness != 0.0 ? "stiffness" : "damping", error);
    EXPECT_LT(error, 1e-6) << c.label;
    if (c.friction && c.friction->kind == FrictionLawKind::kLuGre && c.bearing == Kind::kBody) {
      const Index psi =
          model.rigid_bodies()[model.clearance_joints()[0].bearing.body].rotation_dof();
      const double turning = CalcJacobianError(model, state.q, state.v, weights, psi, 3);
      std::printf("%s, the bearing's ψ columns: relative error %.2e\n", c.label, turning);
      EXPECT_LT(turning, 1e-6) << c.label;
    }
  }
}

const FrictionLaw kTanh = MakeTanhFriction(0.3, 0.2, 1e-1, 1.0);
// μ_s, μ_k, v_s (m/s), σ₀ (1/m), σ₁ (s/m), σ₂ (N s/m).
const FrictionLaw kLuGre = MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1);

TEST(ClearanceJointJacobian, BodyJournalInACablePointBearing) {
  ExpectJacobiansMatch({"revolute body in cable", Kind::kBody, Kind::kPoint,
                        ClearanceJoint::Type::kRevolute, kTanh});
  ExpectJacobiansMatch({"spherical body in cable", Kind::kBody, Kind::kPoint,
                        ClearanceJoint::Type::kSpherical, kTanh});
}

TEST(ClearanceJointJacobian, GroundJournalInABodyAndInACablePoint) {
  ExpectJacobiansMatch({"revolute ground in body", Kind::kGround, Kind::kBody,
                        ClearanceJoint::Type::kRevolute, kTanh});
  ExpectJacobiansMatch({"spherical ground in cable", Kind::kGround, Kind::kPoint,
                        ClearanceJoint::Type::kSpherical, MakeAmbrosioFriction(0.25, 1e-3, 1e-2)});
}

TEST(ClearanceJointJacobian, BodyInBodyAndPointMassInBody) {
  ExpectJacobiansMatch(
      {"revolute body in body", Kind::kBody, Kind::kBody, ClearanceJoint::Type::kRevolute, kTanh});
  ExpectJacobiansMatch({"spherical point mass in body", Kind::kPoint, Kind::kBody,
                        ClearanceJoint::Type::kSpherical, kTanh},
                       /*journal_on_point_mass=*/true);
  ExpectJacobiansMatch({"revolute body in body, frictionless", Kind::kBody, Kind::kBody,
                        ClearanceJoint::Type::kRevolute, std::nullopt});
}

TEST(ClearanceJointJacobian, LuGreBristleInBodyAndCablePointBearings) {
  // A body bearing turns the bristle with it (z_W = R_B z); a cable point's is in world axes.
  ExpectJacobiansMatch({"revolute body in body, LuGre", Kind::kBody, Kind::kBody,
                        ClearanceJoint::Type::kRevolute, kLuGre});
  ExpectJacobiansMatch({"spherical ground in body, LuGre", Kind::kGround, Kind::kBody,
                        ClearanceJoint::Type::kSpherical, kLuGre});
  ExpectJacobiansMatch({"spherical body in cable, LuGre", Kind::kBody, Kind::kPoint,
                        ClearanceJoint::Type::kSpherical, kLuGre});
  ExpectJacobiansMatch({"revolute point mass in body, LuGre", Kind::kPoint, Kind::kBody,
                        ClearanceJoint::Type::kRevolute, kLuGre},
                       /*journal_on_point_mass=*/true);
}

TEST(ClearanceJointForces, ActionAndReactionBalanceAndTheFrictionMomentIsMuNR) {
  // Body in body, revolute, sliding fast enough for the full kinetic coefficient.
  const FrictionLaw coulomb = MakeAmbrosioFriction(0.2, 1e-6, 1e-5);
  const Model model = MakeJointModel(
      {"", Kind::kBody, Kind::kBody, ClearanceJoint::Type::kRevolute, coulomb}, false);
  const State state = MakeInitialState(model);
  Workspace ws(model);
  const ClearanceJointState s =
      CalcClearanceJointState(model, 0, state.q, state.v, ws.body_rotation, ws.joint_history[0]);
  ASSERT_TRUE(s.contact.touching);
  const ClearanceContact& c = s.contact;
  EXPECT_NEAR(c.friction.norm(), 0.2 * c.normal_force, 1e-12 * c.normal_force);
  EXPECT_NEAR(c.journal_moment.norm(), 0.2 * c.normal_force * kJournalRadius,
              1e-12 * c.normal_force);
  // Total force and moment about the origin on the two bodies vanish.
  const VectorXd q_int = CalcJointForces(model, state.q, state.v);
  Vector3d force = Vector3d::Zero();
  Vector3d moment = Vector3d::Zero();
  for (const JointAnchor* anchor :
       {&model.clearance_joints()[0].journal, &model.clearance_joints()[0].bearing}) {
    const RigidBody& body = model.rigid_bodies()[anchor->body];
    const Vector3d x = state.q.segment<3>(body.position_dof());
    const Vector3d f = -q_int.segment<3>(body.position_dof());
    force += f;
    moment += x.cross(f) - body.initial_orientation * q_int.segment<3>(body.rotation_dof());
  }
  EXPECT_LT(force.norm(), 1e-12 * c.normal_force);
  EXPECT_LT(moment.norm(), 1e-12 * c.normal_force);
}

}  // namespace
}  // namespace ancfnet
