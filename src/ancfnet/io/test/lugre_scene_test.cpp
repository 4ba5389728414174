// The LuGre friction law in a scene's contact section: every key read into the model, defaults
// for the optional ones, and bad values reported with file, line and key.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

std::string Scene(const std::string& friction) {
  return R"(gravity: [0, 0, -9.81]
point_masses:
  - {name: block, mass: 0.1, position: [0, 0, 0.0099]}
contact:
  law: {type: linear, stiffness: 1.0e4, damping: 60}
  point_mass_radius: 0.01
  friction: )" +
         friction + R"(
  targets:
    - {name: ground, type: plane, point: [0, 0, 0], normal: [0, 0, 1]}
analysis: {type: dynamic, time_step: 1.0e-4, end_time: 0.01}
)";
}

std::string ErrorOf(const std::string& yaml) {
  try {
    ParseScene(yaml, "scene.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(LuGreScene, ReadsEveryKey) {
  const FrictionLaw law =
      *ParseScene(Scene("{type: lugre, static: 0.5, kinetic: 0.3, stribeck_speed: 0.02, "
                        "bristle_stiffness: 2.0e4, bristle_damping: 80, viscous_damping: 0.1}"))
           .model.contact()
           .friction;
  EXPECT_EQ(law.kind, FrictionLawKind::kLuGre);
  EXPECT_DOUBLE_EQ(law.static_coefficient, 0.5);
  EXPECT_DOUBLE_EQ(law.kinetic_coefficient, 0.3);
  EXPECT_DOUBLE_EQ(law.stribeck_speed, 0.02);
  EXPECT_DOUBLE_EQ(law.bristle_stiffness, 2e4);
  EXPECT_DOUBLE_EQ(law.bristle_damping, 80.0);
  EXPECT_DOUBLE_EQ(law.viscous_damping, 0.1);
}

TEST(LuGreScene, DefaultsTheOptionalKeys) {
  const FrictionLaw law =
      *ParseScene(Scene("{type: lugre, kinetic: 0.3, bristle_stiffness: 1.0e4}"))
           .model.contact()
           .friction;
  EXPECT_DOUBLE_EQ(law.static_coefficient, 0.3);  // μ_s = μ_k
  EXPECT_DOUBLE_EQ(law.stribeck_speed, 1e-2);
  EXPECT_DOUBLE_EQ(law.bristle_damping, 0.0);
  EXPECT_DOUBLE_EQ(law.viscous_damping, 0.0);
}

TEST(LuGreScene, ReportsBadValuesWithLineAndKey) {
  const std::string missing = ErrorOf(Scene("{type: lugre, kinetic: 0.3}"));
  EXPECT_NE(missing.find("scene.yaml:7"), std::string::npos) << missing;
  EXPECT_NE(missing.find("bristle_stiffness"), std::string::npos) << missing;
  const std::string unknown = ErrorOf(
      Scene("{type: lugre, kinetic: 0.3, bristle_stiffness: 1e4, regularization_speed: 1}"));
  EXPECT_NE(unknown.find("regularization_speed"), std::string::npos) << unknown;
  const std::string zero = ErrorOf(Scene("{type: lugre, kinetic: 0, bristle_stiffness: 1e4}"));
  EXPECT_NE(zero.find("kinetic"), std::string::npos) << zero;
  const std::string below =
      ErrorOf(Scene("{type: lugre, static: 0.2, kinetic: 0.3, bristle_stiffness: 1e4}"));
  EXPECT_NE(below.find("static coefficient must be finite and at least the kinetic one"),
            std::string::npos)
      << below;
  EXPECT_NE(below.find("scene.yaml:7"), std::string::npos) << below;
}

}  // namespace
}  // namespace ancfnet
