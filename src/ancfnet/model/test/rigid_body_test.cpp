// Rigid-body kinematics (Rodrigues, the point map G and its transpose), the rebase, and the
// checks on a body's description.

#include <gtest/gtest.h>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

TEST(RigidBodyKinematics, RodriguesMatchesAngleAxisAndSeries) {
  for (const Vector3d& psi :
       {Vector3d(0.3, -1.2, 2.0), Vector3d(1e-5, 2e-5, -1e-5), Vector3d(0.0, 0.0, 3.1)}) {
    const Matrix3d expected = psi.norm() > 0.0
                                  ? Matrix3d(Eigen::AngleAxisd(psi.norm(), psi.normalized()))
                                  : Matrix3d::Identity();
    EXPECT_LT((ExpRotation(psi) - expected).norm(), 1e-15 + 1e-14 * psi.norm());
  }
  EXPECT_LT((ExpRotation(Vector3d::Zero()) - Matrix3d::Identity()).norm(), 1e-16);
}

TEST(RigidBodyKinematics, PointVelocityMapIsTheDerivativeOfTheBodyPoint) {
  // p(t) = x(t) + R(t) s with ẋ = v, R(t) = R₀ exp(t ω̃): ṗ = G (v, ω) at t = 0.
  const Matrix3d r0 =
      Eigen::AngleAxisd(0.8, Vector3d(1.0, -1.0, 2.0).normalized()).toRotationMatrix();
  const Vector3d x0(1.0, 2.0, -0.5), v(0.3, -0.1, 0.4), w(1.3, -0.6, 0.9), s(0.4, 0.2, -0.7);
  const auto point = [&](double t) { return Vector3d(x0 + t * v + r0 * ExpRotation(t * w) * s); };
  const double eps = 1e-6;
  const Vector3d fd = (point(eps) - point(-eps)) / (2.0 * eps);
  const BodyPose pose{x0, r0};
  Vector6d rates;
  rates << v, w;
  const Matrix3x6d g = CalcPointVelocityMap(pose, point(0.0));
  EXPECT_LT((g * rates - fd).norm(), 1e-9);
  // Gᵀ f is the work-conjugate: f · ṗ = (Gᵀ f) · (v, ω), and its moment is Rᵀ((p − x) × f).
  const Vector3d f(2.0, -3.0, 0.5);
  const Vector6d q = CalcGeneralizedForce(pose, point(0.0), f);
  EXPECT_NEAR(f.dot(g * rates), q.dot(rates), 1e-12);
  EXPECT_LT((q - g.transpose() * f).norm(), 1e-13);
  EXPECT_LT((q.tail<3>() - s.cross(r0.transpose() * f)).norm(), 1e-13);
}

Model OneBody(BodyMotion motion) {
  ModelBuilder builder;
  builder.AddRigidBody({.name = "target",
                        .mass = 10.0,
                        .inertia = Vector3d(1.0, 2.0, 2.5).asDiagonal(),
                        .position = Vector3d(1.0, 0.0, 0.0),
                        .orientation = Matrix3d(Eigen::AngleAxisd(0.5, Vector3d::UnitZ())),
                        .velocity = Vector3d(0.1, 0.0, 0.0),
                        .angular_velocity = Vector3d(0.0, 0.0, 2.0),
                        .angular_velocity_in_world = true,
                        .motion = motion});
  return builder.Build();
}

TEST(RigidBody, CoordinatesAndWorldAngularVelocity) {
  const Model model = OneBody(BodyMotion::kFree);
  ASSERT_EQ(model.num_dofs(), 6);
  const RigidBody& body = model.rigid_bodies()[0];
  EXPECT_EQ(body.position_dof(), 0);
  EXPECT_EQ(body.rotation_dof(), 3);
  // ω_W along z, the body turned about z: ω_B = R_WBᵀ ω_W = ω_W.
  EXPECT_LT((model.initial_velocities().tail<3>() - Vector3d(0.0, 0.0, 2.0)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(model.total_mass(), 10.0);
  const State state = MakeInitialState(model);
  ASSERT_EQ(state.body_rotation.size(), 1u);
  EXPECT_LT((state.body_rotation[0] - body.initial_orientation).norm(), 1e-15);
}

TEST(RigidBody, RebaseKeepsThePose) {
  const Model model = OneBody(BodyMotion::kFree);
  State state = MakeInitialState(model);
  state.q.segment<3>(3) = Vector3d(0.2, -0.1, 0.3);
  const BodyPose before = CalcBodyPose(model, state, 0);
  RebaseBodyRotations(model, &state);
  const BodyPose after = CalcBodyPose(model, state, 0);
  EXPECT_LT((after.R_WB - before.R_WB).norm(), 1e-15 * 10);
  EXPECT_EQ(state.q.segment<3>(3).norm(), 0.0);
}

TEST(RigidBody, PrescribedBodyIsEliminatedAndMoving) {
  const Model model = OneBody(BodyMotion::kPrescribed);
  for (bool fixed : model.fixed()) EXPECT_TRUE(fixed);
  EXPECT_LT((model.initial_velocities().head<3>() - Vector3d(0.1, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((model.initial_velocities().tail<3>() - Vector3d(0.0, 0.0, 2.0)).norm(), 1e-15);
  const Model fixed = OneBody(BodyMotion::kFixed);
  EXPECT_EQ(fixed.initial_velocities().norm(), 0.0);
}

TEST(RigidBody, BadDescriptionsAreRefused) {
  const auto add = [](const Matrix3d& inertia, const Matrix3d& orientation, double mass) {
    ModelBuilder builder;
    builder.AddRigidBody(
        {.name = "b", .mass = mass, .inertia = inertia, .orientation = orientation});
  };
  const Matrix3d ok = Vector3d(1.0, 2.0, 2.5).asDiagonal();
  EXPECT_NO_THROW(add(ok, Matrix3d::Identity(), 1.0));
  EXPECT_THROW(add(Vector3d(1.0, 1.0, 2.5).asDiagonal(), Matrix3d::Identity(), 1.0), InputError);
  EXPECT_THROW(add(Vector3d(1.0, -1.0, 1.0).asDiagonal(), Matrix3d::Identity(), 1.0), InputError);
  Matrix3d asymmetric = ok;
  asymmetric(0, 1) = 0.3;
  EXPECT_THROW(add(asymmetric, Matrix3d::Identity(), 1.0), InputError);
  EXPECT_THROW(add(ok, 2.0 * Matrix3d::Identity(), 1.0), InputError);
  EXPECT_THROW(add(ok, -Matrix3d::Identity(), 1.0), InputError);
  EXPECT_THROW(add(ok, Matrix3d::Identity(), 0.0), InputError);
  try {
    add(Vector3d(1.0, 1.0, 2.5).asDiagonal(), Matrix3d::Identity(), 1.0);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle inequality"), std::string::npos) << e.what();
  }
}

TEST(RigidBody, ModalDampingIsRefusedWithFreeBodies) {
  ModelBuilder damped;
  damped.AddRigidBody({.name = "b", .mass = 1.0, .inertia = Matrix3d::Identity()});
  ModalDamping modal;
  modal.num_modes = 1;
  modal.ratios = {0.01};
  damped.SetModalDamping(modal);
  EXPECT_THROW(damped.Build(), InputError);
}

TEST(RigidBody, AttachmentsNeedAKnownBodyAndAStepForTheDefaultStiffness) {
  ModelBuilder builder;
  builder.AddRigidBody({.name = "b", .mass = 2.0, .inertia = Matrix3d::Identity()});
  builder.AddPointMass("m", 1.0, Vector3d(1.0, 0.0, 0.0));
  EXPECT_THROW(builder.AddBodyAttachment({.name = "a", .body = "nobody", .point = {"m"}}),
               InputError);
  EXPECT_THROW(builder.AddBodyAttachment({.name = "a", .body = "b", .point = {"m"}}), InputError);
  builder.AddBodyAttachment({.name = "a", .body = "b", .point = {"m"}, .time_step = 1e-2});
  const Model model = builder.Build();
  const BodyAttachment& a = model.body_attachments()[0];
  // Where the point is; k = m_eff (10/h)², m_eff = 1·2/3; c = 2 √(k m_eff).
  EXPECT_LT((a.body_point - Vector3d(1.0, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_NEAR(a.stiffness, (2.0 / 3.0) * 1e6, 1e-6);
  EXPECT_NEAR(a.damping, 2.0 * std::sqrt(a.stiffness * 2.0 / 3.0), 1e-9);
}

}  // namespace
}  // namespace ancfnet
