// Scene files with clearance joints: every key read into the model (anchors on a body, a cable
// point, a point mass and the ground), the joint probe's columns, LuGre friction, and bad input
// reported with file, line and key.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

constexpr const char* kJoints = R"(materials:
  steel: {youngs_modulus: 2.0e11, density: 7800}
sections:
  arm: {shape: circle, diameter: 0.01}
point_masses:
  - {name: ball, mass: 0.1, position: [1, 1, 0]}
cables:
  - {name: arm, start: [0, 0, 0], end: [0.4, 0, 0], elements: 2, material: steel, section: arm}
bodies:
  - name: pin
    mass: 0.5
    inertia: [1.0e-4, 1.0e-4, 1.0e-4]
    position: [0.5, 0, 0]
    orientation: {axis: [0, 0, 1], angle: 1.5707963267948966}
joints:
  - name: tip
    type: revolute_clearance
    journal: {body: pin, point: [0.4, 0, 0]}
    bearing: arm.end
    clearance: 0.5e-3
    journal_radius: 0.01
    axis: [0, 0, 3]
    contact: {type: hertz, stiffness: 1.0e9}
    friction: {type: tanh, kinetic: 0.1}
  - {name: socket, type: spherical_clearance, journal: ball, bearing: ground, clearance: 1.0e-3,
     journal_radius: 0.005, contact: {type: flores, stiffness: 1.0e8, restitution: 0.8}}
probes:
  - {name: orbit, quantity: clearance_joint, joint: tip}
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(ClearanceJointScene, ReadsEveryKey) {
  const Scene scene = ParseScene(kJoints);
  const auto& joints = scene.model.clearance_joints();
  ASSERT_EQ(joints.size(), 2u);
  const ClearanceJoint& tip = joints[0];
  EXPECT_EQ(tip.type, ClearanceJoint::Type::kRevolute);
  EXPECT_EQ(tip.journal.kind, JointAnchor::Kind::kBody);
  // The journal's centre (0.4, 0, 0) in the frame of the pin turned by 90° about z.
  EXPECT_LT((tip.journal.body_point - Vector3d(0, 0.1, 0)).norm(), 1e-12);
  EXPECT_EQ(tip.bearing.kind, JointAnchor::Kind::kPoint);
  EXPECT_TRUE(tip.bearing.has_slope);
  EXPECT_EQ(tip.bearing.num_blocks, 4);
  EXPECT_DOUBLE_EQ(tip.clearance, 0.5e-3);
  EXPECT_DOUBLE_EQ(tip.journal_radius, 0.01);
  EXPECT_LT((tip.axis - Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_EQ(tip.normal.kind, NormalLawKind::kHertz);
  ASSERT_TRUE(tip.friction.has_value());
  EXPECT_EQ(tip.friction->kind, FrictionLawKind::kTanh);
  const ClearanceJoint& socket = joints[1];
  EXPECT_EQ(socket.type, ClearanceJoint::Type::kSpherical);
  EXPECT_EQ(socket.journal.kind, JointAnchor::Kind::kPoint);
  EXPECT_FALSE(socket.journal.has_slope);
  // The ground bearing sits where the ball starts.
  EXPECT_EQ(socket.bearing.kind, JointAnchor::Kind::kGround);
  EXPECT_LT((socket.bearing.ground_point - Vector3d(1, 1, 0)).norm(), 1e-15);
  EXPECT_FALSE(socket.friction.has_value());
  ASSERT_EQ(scene.probes.size(), 1u);
  EXPECT_EQ(ProbeColumns(scene.probes[0]),
            (std::vector<std::string>{"orbit.ex", "orbit.ey", "orbit.ez", "orbit.penetration",
                                      "orbit.normal_force", "orbit.friction_force",
                                      "orbit.friction_moment", "orbit.mode"}));
}

TEST(ClearanceJointScene, ReadsLuGreFriction) {
  const std::string text =
      Replace(kJoints, "friction: {type: tanh, kinetic: 0.1}",
              "friction: {type: lugre, static: 0.4, kinetic: 0.3, stribeck_speed: 0.02,\n"
              "               bristle_stiffness: 2.0e4, bristle_damping: 80}");
  const Scene scene = ParseScene(text);
  const auto& friction = scene.model.clearance_joints()[0].friction;
  ASSERT_TRUE(friction.has_value());
  EXPECT_EQ(friction->kind, FrictionLawKind::kLuGre);
  EXPECT_DOUBLE_EQ(friction->static_coefficient, 0.4);
  EXPECT_DOUBLE_EQ(friction->kinetic_coefficient, 0.3);
  EXPECT_DOUBLE_EQ(friction->stribeck_speed, 0.02);
  EXPECT_DOUBLE_EQ(friction->bristle_stiffness, 2e4);
  EXPECT_DOUBLE_EQ(friction->bristle_damping, 80.0);
}

// The message of ParseScene(text), or "" when it is accepted.
std::string ErrorOf(const std::string& text) {
  try {
    ParseScene(text);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ClearanceJointScene, BadInputNamesLineAndKey) {
  const std::string base = kJoints;
  const struct {
    const char* from;
    const char* to;
    const char* expected;
  } cases[] = {
      {"clearance: 0.5e-3", "clearance: 0", "<string>:20:16: expected a number > 0"},
      {"journal_radius: 0.01", "journal_radius: 0.4e-3",
       "<string>:21:21: the journal radius must be larger than the clearance"},
      {"axis: [0, 0, 3]", "axis: [0, 0, 0]", "<string>:22:11: the joint axis must be a non-zero"},
      {"{body: pin, point", "{body: pan, point",
       "<string>:18:14: journal: no rigid body named 'pan'"},
      {"bearing: arm.end", "bearing: ram.end", "<string>:19:14: bearing:"},
      {"journal: ball, bearing: ground", "journal: ground, bearing: ground",
       "journal and bearing are both the ground"},
      // (`revolute` is an ideal joint: the list names both kinds.)
      {"type: revolute_clearance", "type: revolute_clearence",
       "<string>:17:11: expected one of spherical, revolute, "},
      // The LuGre law's keys as under contact: a missing σ₀, a negative σ₁.
      {"friction: {type: tanh, kinetic: 0.1}", "friction: {type: lugre, kinetic: 0.1}",
       "<string>:24:15: missing required key 'bristle_stiffness' in 'friction'"},
      {"friction: {type: tanh, kinetic: 0.1}",
       "friction: {type: lugre, kinetic: 0.1, bristle_stiffness: 1.0e4, bristle_damping: -5}",
       "<string>:24:86: expected a number ≥ 0, got '-5' (key 'bristle_damping')"},
      {"joint: tip", "joint: top", "no clearance joint named 'top'"},
  };
  for (const auto& c : cases) {
    const std::string message = ErrorOf(Replace(base, c.from, c.to));
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.from << " → " << message;
  }
}

}  // namespace
}  // namespace ancfnet
