// The `contact:` reader: a law without a type is Carvalho–Martins (the default for nets);
// `penetration_increment` is read and a negative one refused; `target_geometry` is spheres by
// default, capsules on request (with `capsules_per_element`, or automatic); bad values are
// InputErrors naming the line.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

// A 0.2 m rope of 2 elements, 2 mm thick, over a sphere; `contact_lines` start at line 9.
std::string SceneWith(const std::string& contact_lines) {
  return R"(materials:
  nylon: {youngs_modulus: 1.0e9, density: 1000}
sections:
  rope: {shape: circle, diameter: 0.002}
cables:
  - {name: rope, start: [0, 0, 0.1], end: [0.2, 0, 0.1], elements: 2, material: nylon,
     section: rope}
contact:
)" + contact_lines +
         R"(  targets:
    - {name: ball, type: sphere, center: [0.1, 0, 0], radius: 0.05}
analysis:
  type: dynamic
  time_step: 1.0e-3
  end_time: 0.01
)";
}

const std::string kLinear = "  law: {type: linear, stiffness: 1.0e4}\n";

TEST(ContactLawReader, ALawWithoutATypeIsCarvalhoMartins) {
  const Scene scene =
      ParseScene(SceneWith("  law: {stiffness: 2.0e6, restitution: 0.4}\n"), "scene.yaml");
  const NormalLaw& law = scene.model.contact().normal;
  EXPECT_EQ(law.kind, NormalLawKind::kCarvalhoMartins);
  EXPECT_EQ(law.stiffness, 2.0e6);
  EXPECT_EQ(law.restitution, 0.4);
  EXPECT_DOUBLE_EQ(law.hysteresis_factor(),
                   CalcHysteresisFactor(NormalLawKind::kCarvalhoMartins, 0.4));
  EXPECT_EQ(scene.model.contact().penetration_increment, 0.05);  // the default
}

TEST(ContactLawReader, PenetrationIncrementIsReadAndANegativeOneRefused) {
  const std::string law = "  law: {type: hertz, stiffness: 1.0e6}\n";
  const Scene off = ParseScene(SceneWith(law + "  penetration_increment: 0\n"), "scene.yaml");
  EXPECT_EQ(off.model.contact().penetration_increment, 0.0);
  try {
    ParseScene(SceneWith(law + "  penetration_increment: -0.1\n"), "scene.yaml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("scene.yaml:10"), std::string::npos) << message;
    EXPECT_NE(message.find("penetration_increment"), std::string::npos) << message;
  }
}

TEST(TargetGeometryReader, SpheresByDefaultCapsulesOnRequest) {
  const Scene spheres = ParseScene(SceneWith(kLinear), "scene.yaml");
  EXPECT_EQ(spheres.model.contact().target_geometry, ContactSpec::TargetGeometry::kSpheres);
  // Automatic: one sphere per diameter, ⌈0.1 / 0.002⌉ = 50, at most 32 per element.
  EXPECT_EQ(MakeContactProbes(spheres.model).size(), 64u);

  const Scene given = ParseScene(
      SceneWith(kLinear + "  target_geometry: capsules\n  capsules_per_element: 3\n"), "s.yaml");
  EXPECT_EQ(given.model.contact().target_geometry, ContactSpec::TargetGeometry::kCapsules);
  const std::vector<ContactProbe> probes = MakeContactProbes(given.model);
  ASSERT_EQ(probes.size(), 6u);
  EXPECT_DOUBLE_EQ(probes[1].xi0, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(probes[1].xi1, 2.0 / 3.0);

  // Automatic: one capsule per 8 radii, ⌈0.1 / 0.008⌉ = 13, at most 8 per element.
  const Scene automatic =
      ParseScene(SceneWith(kLinear + "  target_geometry: capsules\n"), "s.yaml");
  EXPECT_EQ(MakeContactProbes(automatic.model).size(), 16u);
  EXPECT_EQ(CountContactPairs(automatic.model), 16);
}

TEST(TargetGeometryReader, UnknownGeometryIsAnInputErrorNamingTheLine) {
  try {
    ParseScene(SceneWith(kLinear + "  target_geometry: cylinders\n"), "scene.yaml");
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("scene.yaml:10"), std::string::npos) << message;
    EXPECT_NE(message.find("capsules"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace ancfnet
