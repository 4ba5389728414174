// Study files: their parameters and cases, the case scenes, and every refusal with file, line
// and key.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/io/test/output_test_files.hpp"
#include "ancfnet/study/study.hpp"

namespace ancfnet {
namespace {

constexpr const char* kBaseScene = R"(gravity: [0, 0, 0]
materials:
  dyneema: {youngs_modulus: 1.0e10, density: 970}
sections:
  thread: {shape: circle, diameter: 0.002}
bodies:
  - name: target
    mass: 50
    inertia: [1, 1.2, 1.4]
    position: [0, 0, 0]
    angular_velocity: [0.3, 0.5, 0.2]
nets:
  - {name: net, type: square, side: 0.8, meshes: 2, center: [0, 0, 0.3], material: dyneema,
     section: thread, velocity: [0, 0, -4.0]}
contact:
  law: {type: carvalho_martins, stiffness: 1.0e8, restitution: 0.3}
  targets:
    - {name: hull, type: box, body: target, center: [0, 0, 0], half_extents: [0.15, 0.15, 0.15]}
analysis: {type: dynamic, time_step: 1.0e-3, end_time: 0.002}
)";

// A study file `text` beside the base scene base.yaml, in a folder of the running test.
Study Parse(const std::string& text) {
  const std::filesystem::path dir = test::MakeTestDirectory();
  std::ofstream(dir / "base.yaml") << kBaseScene;
  return ParseStudy(text, "study.yaml", dir);
}

// Expects `text` to be refused at `line` of study.yaml with a message holding `words`.
void ExpectRefused(const std::string& text, int line, const std::string& words) {
  try {
    Parse(text);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with("study.yaml:" + std::to_string(line) + ":")) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}

TEST(StudyFile, GridStudyMakesEveryCaseScene) {
  const Study study = Parse(
      "scene: base.yaml\n"
      "parameters:\n"
      "  - {path: 'nets[net].velocity[2]', values: [-3, -5.5]}\n"
      "  - {path: 'bodies[0].angular_velocity[2]', values: [0, 0.1, 0.2]}\n"
      "  - {path: contact.law.stiffness, values: [2.0e7]}\n"
      "set: {analysis.end_time: 0.001}\n");
  const CaseTable cases = study.MakeCases();
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[4], (std::vector<double>{-5.5, 0.1, 2.0e7}));
  const std::string text = study.MakeCaseScene(cases[4]);
  const Scene scene = ParseScene(text, "case.yaml");
  EXPECT_EQ(scene.model.rigid_bodies().size(), 1u);
  const YAML::Node node = YAML::Load(text);
  EXPECT_EQ(node["nets"][0]["velocity"][2].as<double>(), -5.5);
  EXPECT_EQ(node["bodies"][0]["angular_velocity"][2].as<double>(), 0.1);
  EXPECT_EQ(node["bodies"][0]["angular_velocity"][1].as<double>(), 0.5);  // untouched
  EXPECT_EQ(node["contact"]["law"]["stiffness"].as<double>(), 2.0e7);
  EXPECT_EQ(node["analysis"]["end_time"].as<double>(), 0.001);
  // The base scene itself is left as it was.
  EXPECT_EQ(study.scene["nets"][0]["velocity"][2].as<double>(), -4.0);
}

TEST(StudyFile, SampledValuesFollowTheirDistributions) {
  const Study study = Parse(
      "scene: base.yaml\n"
      "sampling: latin_hypercube\n"
      "cases: 400\n"
      "seed: 5\n"
      "parameters:\n"
      "  - {path: 'nets[0].velocity[2]', uniform: [-6, -2]}\n"
      "  - {path: contact.law.restitution, normal: {mean: 0.3, std: 0.01}}\n");
  const CaseTable cases = study.MakeCases();
  ASSERT_EQ(cases.size(), 400u);
  double sum = 0.0, square = 0.0;
  for (const std::vector<double>& row : cases) {
    EXPECT_GT(row[0], -6.0);
    EXPECT_LT(row[0], -2.0);
    sum += row[1];
    square += row[1] * row[1];
  }
  const double mean = sum / 400.0;
  EXPECT_NEAR(mean, 0.3, 1e-3);
  EXPECT_NEAR(std::sqrt(square / 400.0 - mean * mean), 0.01, 1e-3);
  EXPECT_EQ(cases, study.MakeCases());
}

TEST(StudyFile, PathsTheBaseSceneLacksAreRefused) {
  const std::string head = "scene: base.yaml\nparameters:\n";
  ExpectRefused(head + "  - {path: contact.law.stifness, values: [1]}\n", 3,
                "no key 'stifness' in 'contact.law'; did you mean 'stiffness'?");
  ExpectRefused(head + "  - {path: 'bodies[2].mass', values: [1]}\n", 3,
                "no item [2] in 'bodies' (a list of 1 items)");
  ExpectRefused(head + "  - {path: 'bodies[chaser].mass', values: [1]}\n", 3,
                "no item named 'chaser' in 'bodies'");
  ExpectRefused(head + "  - {path: contact.law, values: [1]}\n", 3,
                "'contact.law' of the scene base.yaml is not a number");
  ExpectRefused(head + "  - {path: 'contact..law', values: [1]}\n", 3, "not a scene path");
  ExpectRefused(head + "  - {path: 'gravity.x', values: [1]}\n", 3, "is not a map");
  ExpectRefused(head + "  - {path: 'nets[0].type', values: [1]}\n", 3, "is not a number");
}

TEST(StudyFile, BadStudiesAreRefusedWithLineAndKey) {
  ExpectRefused("scene: base.yaml\nparameter: []\n", 2, "key 'parameter'");
  ExpectRefused("scene: base.yaml\nparameters: []\n", 2, "parameters");
  ExpectRefused("scene: missing.yaml\nparameters: []\n", 1, "cannot open the base scene");
  const std::string grid = "scene: base.yaml\nparameters:\n  - path: contact.law.stiffness\n";
  ExpectRefused(grid + "    uniform: [1, 2]\n", 4, "a grid study lists each parameter's");
  ExpectRefused(grid + "    values: []\n", 4, "values");
  ExpectRefused(grid + "    values: [1]\n  - {path: contact.law.stiffness, values: [2]}\n", 5,
                "already a parameter");
  ExpectRefused(grid + "    values: [1]\ncases: 3\n", 5, "a grid study has one case per");
  ExpectRefused(grid + "    values: [1]\nset: {contact.law.stiffness: 2}\n", 5,
                "is a parameter of the study");
  ExpectRefused(grid + "    values: [1]\nset: {analysis.end_tim: 2}\n", 5,
                "no key 'end_tim' in 'analysis'; did you mean 'end_time'?");
  const std::string sampled =
      "scene: base.yaml\nsampling: random\ncases: 4\nparameters:\n"
      "  - path: contact.law.stiffness\n";
  ExpectRefused(sampled + "    uniform: [2, 1]\n", 6, "LOW must be below HIGH");
  ExpectRefused(sampled + "    uniform: [1]\n", 6, "[LOW, HIGH]");
  ExpectRefused(sampled + "    normal: {mean: 1, std: 0}\n", 6, "key 'std'");
  ExpectRefused(sampled + "    normal: {mean: 1, sd: 2}\n", 6, "key 'sd'");
  ExpectRefused(sampled + "    values: [1]\n", 6, "a sampled study gives each parameter");
  ExpectRefused(sampled + "    gamma: [1]\n", 6, "key 'gamma'");
  ExpectRefused(
      "scene: base.yaml\nsampling: random\ncases: 0\nparameters:\n"
      "  - {path: contact.law.stiffness, uniform: [1, 2]}\n",
      3, "key 'cases'");
  ExpectRefused(
      "scene: base.yaml\nsampling: random\nparameters:\n"
      "  - {path: contact.law.stiffness, uniform: [1, 2]}\n",
      1, "missing required key 'cases'");
  ExpectRefused("scene: base.yaml\nsampling: sobol\n", 2, "key 'sampling'");
  ExpectRefused(grid +
                    "    values: [1]\nplot: {x: contact.law.stiffness, y: 'gravity[0]', "
                    "metric: m}\n",
                5, "key 'y'");
}

TEST(StudyFile, ExampleStudiesLoad) {
  const char* root = std::getenv("ANCFNET_SOURCE_DIR");
  const std::filesystem::path examples = std::filesystem::path(root ? root : ".") / "examples";
  int studies = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    if (!entry.path().filename().string().starts_with("study_")) continue;
    SCOPED_TRACE(entry.path().string());
    const Study study = LoadStudy(entry.path());
    EXPECT_FALSE(study.MakeCases().empty());
    ++studies;
  }
  EXPECT_GE(studies, 1);
}

}  // namespace
}  // namespace ancfnet
