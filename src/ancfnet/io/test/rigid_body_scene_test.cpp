// Scene files with rigid bodies, attachments and body probes: every key read into the model, and
// bad input reported with file, line and key.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

constexpr const char* kBodies = R"(gravity: [0, 0, -9.81]
point_masses:
  - {name: bob, mass: 2.0, position: [0, 0, -1]}
bodies:
  - name: target
    mass: 100
    inertia: [10, 20, 25]
    position: [0, 0, 0]
    orientation: {axis: [0, 0, 1], angle: 1.5707963267948966}
    velocity: [0.1, 0, 0]
    angular_velocity: [1, 0, 0]
    angular_velocity_frame: world
  - {name: hub, mass: 5, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 1.5]], position: [3, 0, 0],
     orientation: {quaternion: [1, 0, 0, 0]}, motion: fixed}
attachments:
  - {name: hook, body: target, point: bob}
  - {name: spring, body: hub, point: bob, body_point: [0, 0, 1], stiffness: 300, damping: 2}
probes:
  - {name: pose, quantity: body_pose, body: target}
  - {name: rates, quantity: body_velocity, body: target}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.1}
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string ErrorOf(const std::string& text) {
  try {
    ParseScene(text, "scene.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RigidBodyScene, ReadsBodiesAttachmentsAndProbes) {
  const Scene scene = ParseScene(kBodies);
  const Model& model = scene.model;
  ASSERT_EQ(model.rigid_bodies().size(), 2u);
  const RigidBody& target = model.rigid_bodies()[0];
  EXPECT_DOUBLE_EQ(target.mass, 100.0);
  EXPECT_DOUBLE_EQ(target.inertia(2, 2), 25.0);
  EXPECT_EQ(target.motion, BodyMotion::kFree);
  EXPECT_EQ(model.rigid_bodies()[1].motion, BodyMotion::kFixed);
  // Turned 90° about z: ω_W = x is ω_B = −y.
  EXPECT_LT(
      (model.initial_velocities().segment<3>(target.rotation_dof()) - Vector3d(0, -1, 0)).norm(),
      1e-12);
  ASSERT_EQ(model.body_attachments().size(), 2u);
  const BodyAttachment& hook = model.body_attachments()[0];
  // Where the bob is, in body axes: R_WBᵀ (0, 0, −1) = (0, 0, −1); fixed: k = m_eff (10/h)².
  EXPECT_LT((hook.body_point - Vector3d(0, 0, -1)).norm(), 1e-12);
  const double reduced = 2.0 * 100.0 / 102.0;
  EXPECT_NEAR(hook.stiffness, reduced * 1e8, 1e-3);
  EXPECT_DOUBLE_EQ(model.body_attachments()[1].stiffness, 300.0);
  EXPECT_DOUBLE_EQ(model.body_attachments()[1].damping, 2.0);

  ASSERT_EQ(scene.probes.size(), 2u);
  EXPECT_EQ(ProbeColumns(scene.probes[0])[3], "pose.qw");
  const State state = MakeInitialState(model);
  std::vector<double> values;
  EvaluateProbe(scene.probes[0], model, state, {}, {}, &values);
  EvaluateProbe(scene.probes[1], model, state, {}, {}, &values);
  ASSERT_EQ(values.size(), 13u);
  EXPECT_NEAR(values[3], std::cos(0.25 * 3.141592653589793), 1e-12);  // qw of 90° about z
  EXPECT_NEAR(values[6], std::sin(0.25 * 3.141592653589793), 1e-12);  // qz
  EXPECT_NEAR(values[7], 0.1, 1e-15);
  EXPECT_NEAR(values[11], -1.0, 1e-12);  // ω_B,y
}

TEST(RigidBodyScene, BadInputIsReportedWithItsPlace) {
  EXPECT_NE(ErrorOf(Replace(kBodies, "[10, 20, 25]", "[10, 10, 25]")).find("scene.yaml:7"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "[10, 20, 25]", "[10, 10, 25]")).find("triangle"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "body: target, point: bob}", "body: targt, point: bob}"))
                .find("no rigid body named 'targt'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "motion: fixed", "motion: frozen")).find("motion"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "[1, 0, 0, 0]", "[0, 0, 0, 0]")).find("quaternion"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "quantity: body_pose, body: target",
                            "quantity: body_pose, body: nobody"))
                .find("no rigid body named 'nobody'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kBodies, "name: hub", "name: bob")).find("already named 'bob'"),
            std::string::npos);
}

TEST(RigidBodyScene, StaticAnalysisRefusesFreeBodies) {
  const Scene scene = ParseScene(kBodies);
  State state = MakeInitialState(scene.model);
  EXPECT_THROW(SolveStatic(scene.model, {}, nullptr, &state), InputError);
}

}  // namespace
}  // namespace ancfnet
