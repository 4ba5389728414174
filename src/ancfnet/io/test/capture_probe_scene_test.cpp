// The capture probe in a scene: its columns, the errors of its keys (file, line, key), and a net
// dropped flat onto a sphere whose first contact time follows free fall.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/run/run_scene.hpp"

namespace ancfnet {
namespace {

// The scene of examples/net_drop_sphere.yaml: a 1 m square net of 10 × 10 meshes, flat at
// z = 0.34 m, falling from rest onto a ball of radius 0.3 m whose top is under its centre knot;
// and a plane far below.
constexpr const char* kScene = R"(gravity: [0, 0, -9.81]
materials:
  thread: {youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-4}
sections:
  thread: {shape: circle, diameter: 0.002}
nets:
  - {name: net, type: square, side: 1.0, meshes: 10, center: [0, 0, 0.34], material: thread,
     section: thread, tension_only: false}
contact:
  law: {type: carvalho_martins, stiffness: 1.0e6, restitution: 0.3}
  points_per_element: 8
  targets:
    - {name: ball, type: sphere, center: [0, 0, 0], radius: 0.3}
    - {name: floor, type: plane, point: [0, 0, -5], normal: [0, 0, 1]}
probes:
  - {name: grab, quantity: capture, net: net, target: ball}
analysis:
  type: dynamic
  integrator: midpoint
  time_step: 5.0e-4
  end_time: 0.11
output:
  interval: 0.01
)";

std::string ErrorOf(const std::string& yaml) {
  try {
    ParseScene(yaml, "scene.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(CaptureProbe, ReadsNetAndTargetAndNamesItsColumns) {
  const Scene scene = ParseScene(kScene, "scene.yaml");
  ASSERT_EQ(scene.probes.size(), 1u);
  const Probe& probe = scene.probes[0];
  EXPECT_EQ(probe.quantity, ProbeQuantity::kCapture);
  EXPECT_EQ(probe.net, 0);
  EXPECT_EQ(probe.target, 0);
  EXPECT_NEAR(probe.reference_area, 1.0, 1e-12);  // the 1 m square
  EXPECT_EQ(ProbeColumns(probe),
            (std::vector<std::string>{"grab.contact", "grab.enclosed", "grab.mouth_ratio",
                                      "grab.knot_coverage", "grab.thread_coverage",
                                      "grab.thread_tension", "grab.thread_load",
                                      "grab.tether_tension", "grab.tether_load", "grab.escaped"}));
}

TEST(CaptureProbe, RefusesAPlaneAMissingTargetAndAnUnknownNet) {
  const std::string probe = "{name: grab, quantity: capture, net: net, target: ball}";
  EXPECT_EQ(ErrorOf(Replace(kScene, probe,
                            "{name: grab, quantity: capture, net: net, "
                            "target: floor}")),
            "scene.yaml:16:55: a capture probe needs a bounded target (sphere, box, cylinder, "
            "capsule, mesh), not a plane (key 'target')");
  EXPECT_NE(ErrorOf(Replace(kScene, probe, "{name: grab, quantity: capture, net: net}"))
                .find("scene.yaml:16"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Replace(kScene, probe,
                            "{name: grab, quantity: capture, net: nett, "
                            "target: ball}"))
                .find("no net named 'nett'"),
            std::string::npos);
}

TEST(CaptureProbe, NetDroppedOnABallFirstTouchesItAfterFreeFall) {
  // The lowest inspection spheres (radius 1 mm, the nearest 6.25 mm from the ball's top) start
  // h = 0.34 − 0.001 − 0.29993 m above the ball: free fall reaches it at t_c = √(2h/g) = 0.0893 s.
  // The first contact time is the first output in contact: not before t_c, and (the threads
  // bounce on the ball between outputs) within two output intervals of it.
  const Scene scene = ParseScene(kScene, "scene.yaml");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("ancfnet_capture_" +
       std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::remove_all(dir);
  RunOptions options;
  options.output_dir = dir;
  const RunSummary summary = RunScene(scene, options);
  ASSERT_TRUE(summary.completed) << summary.message;
  const double h = 0.34 - 0.001 - std::sqrt(0.09 - 0.00625 * 0.00625);
  const double contact_time = std::sqrt(2.0 * h / 9.81);
  const double first = summary.first_contact_times.at("grab");
  EXPECT_GE(first, contact_time);
  EXPECT_LE(first, contact_time + 0.02);
  std::ifstream file(dir / "summary.json");
  const nlohmann::json json = nlohmann::json::parse(file);
  const nlohmann::json& capture = json["probes"]["grab"]["capture"];
  EXPECT_EQ(capture["first_contact_time"].get<double>(), first);
  EXPECT_GT(capture["thread_coverage"].get<double>(), 0.0);
  EXPECT_EQ(capture["knot_coverage"].get<double>(), 0.0);   // knots have no contact radius
  EXPECT_TRUE(capture["thread_breaking_force"].is_null());  // unbreakable threads
  EXPECT_TRUE(capture["thread_safety_factor"].is_null());
  EXPECT_TRUE(capture["tether"].is_null());
  EXPECT_FALSE(capture["escaped"].get<bool>());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ancfnet
