// The `contact:` keys for the normal law and the step control: a law without a type is
// Carvalho–Martins (the default for nets), `penetration_increment` is read, and a negative one is
// an InputError naming the line.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

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
    - {name: ground, type: plane, point: [0, 0, 0], normal: [0, 0, 1]}
analysis:
  type: dynamic
  time_step: 1.0e-3
  end_time: 0.01
)";
}

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

}  // namespace
}  // namespace ancfnet
