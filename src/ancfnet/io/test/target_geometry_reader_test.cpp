// The `target_geometry` key of `contact:`: spheres by default, capsules on request (with
// `capsules_per_element`, or automatic), and a clear error for anything else.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

// A 0.2 m rope of 2 elements, 2 mm thick, over a sphere.
std::string SceneWith(const std::string& geometry_lines) {
  return R"(materials:
  nylon: {youngs_modulus: 1.0e9, density: 1000}
sections:
  rope: {shape: circle, diameter: 0.002}
cables:
  - {name: rope, start: [0, 0, 0.1], end: [0.2, 0, 0.1], elements: 2, material: nylon,
     section: rope}
contact:
  law: {type: linear, stiffness: 1.0e4}
)" + geometry_lines +
         R"(  targets:
    - {name: ball, type: sphere, center: [0.1, 0, 0], radius: 0.05}
analysis:
  type: dynamic
  time_step: 1.0e-3
  end_time: 0.01
)";
}

TEST(TargetGeometryReader, SpheresByDefaultCapsulesOnRequest) {
  const Scene spheres = ParseScene(SceneWith(""), "scene.yaml");
  EXPECT_EQ(spheres.model.contact().target_geometry, ContactSpec::TargetGeometry::kSpheres);
  // Automatic: one sphere per diameter, ⌈0.1 / 0.002⌉ = 50, at most 32 per element.
  EXPECT_EQ(MakeContactProbes(spheres.model).size(), 64u);

  const Scene given =
      ParseScene(SceneWith("  target_geometry: capsules\n  capsules_per_element: 3\n"), "s.yaml");
  EXPECT_EQ(given.model.contact().target_geometry, ContactSpec::TargetGeometry::kCapsules);
  const std::vector<ContactProbe> probes = MakeContactProbes(given.model);
  ASSERT_EQ(probes.size(), 6u);
  EXPECT_DOUBLE_EQ(probes[1].xi0, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(probes[1].xi1, 2.0 / 3.0);

  // Automatic: one capsule per 8 radii, ⌈0.1 / 0.008⌉ = 13, at most 8 per element.
  const Scene automatic = ParseScene(SceneWith("  target_geometry: capsules\n"), "s.yaml");
  EXPECT_EQ(MakeContactProbes(automatic.model).size(), 16u);
  EXPECT_EQ(CountContactPairs(automatic.model), 16);
}

TEST(TargetGeometryReader, UnknownGeometryIsAnInputErrorNamingTheLine) {
  try {
    ParseScene(SceneWith("  target_geometry: cylinders\n"), "scene.yaml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("scene.yaml:10"), std::string::npos) << message;
    EXPECT_NE(message.find("capsules"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace ancfnet
