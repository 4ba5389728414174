#include "ancfnet/io/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "ancfnet/common/error.hpp"
#include "cantilever_scene.hpp"

namespace ancfnet {
namespace {

using test::Cantilever;
using test::ErrorOf;
using test::kCantilever;
using test::Replace;

// The folder of the repository (CTest sets ANCFNET_SOURCE_DIR; by hand, run from the root).
std::filesystem::path SourceDir() {
  const char* dir = std::getenv("ANCFNET_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::current_path();
}

TEST(SceneLoaderTest, CantileverHasTheRightModel) {
  const Scene scene = ParseScene(kCantilever);
  const Model& model = scene.model;
  EXPECT_EQ(scene.source, "<string>");
  ASSERT_EQ(model.cables().size(), 1u);
  const Cable& beam = model.cables()[0];
  EXPECT_EQ(beam.name, "beam");
  EXPECT_EQ(beam.num_elements, 16);
  EXPECT_DOUBLE_EQ(beam.length, 1.0);
  EXPECT_DOUBLE_EQ(beam.properties.axial_stiffness, 2e11 * 1e-4);
  EXPECT_DOUBLE_EQ(beam.properties.bending_stiffness, 2e11 * 1e-8 / 12.0);
  EXPECT_DOUBLE_EQ(beam.properties.mass_per_length, 7800 * 1e-4);
  EXPECT_FALSE(beam.properties.tension_only);
  EXPECT_EQ(beam.properties.axial_gauss_points, 3);
  EXPECT_EQ(beam.properties.bending_gauss_points, 4);
  EXPECT_EQ(model.num_nodes(), 17);
  EXPECT_EQ(model.num_dofs(), 102);
  EXPECT_EQ(model.gravity(), Vector3d::Zero());

  // The clamp fixes the six coordinates of the first node, and only those.
  EXPECT_EQ(std::count(model.fixed().begin(), model.fixed().end(), true), 6);
  for (int k = 0; k < 6; ++k) EXPECT_TRUE(model.fixed()[k]);

  ASSERT_EQ(model.point_forces().size(), 1u);
  EXPECT_EQ(model.point_forces()[0].point.element, 15);
  EXPECT_DOUBLE_EQ(model.point_forces()[0].point.xi, 1.0);
  EXPECT_EQ(model.point_forces()[0].force, Vector3d(0, 0, -333.333));
  EXPECT_TRUE(model.point_moments().empty());
  EXPECT_TRUE(model.distributed_loads().empty());
}

TEST(SceneLoaderTest, CantileverHasTheRightProbesAndSettings) {
  const Scene scene = ParseScene(kCantilever);
  ASSERT_EQ(scene.probes.size(), 1u);
  EXPECT_EQ(scene.probes[0].name, "tip");
  EXPECT_EQ(scene.probes[0].quantity, ProbeQuantity::kPosition);
  // The tip: the end of element 15, at (1, 0, 0).
  EXPECT_EQ(scene.probes[0].point.dof[2], scene.model.elements()[15].dofs[6]);
  EXPECT_DOUBLE_EQ(scene.probes[0].point.weight[2], 1.0);
  EXPECT_TRUE(Model::Locate(scene.probes[0].point, scene.model.initial_positions())
                  .isApprox(Vector3d(1, 0, 0)));

  const AnalysisSettings defaults;
  EXPECT_EQ(scene.analysis.type, AnalysisType::kStatic);
  EXPECT_EQ(scene.analysis.statics.load_steps, 10);
  EXPECT_EQ(scene.analysis.statics.max_step_cuts, defaults.statics.max_step_cuts);
  EXPECT_EQ(scene.analysis.statics.newton.max_iterations, defaults.statics.newton.max_iterations);
  EXPECT_DOUBLE_EQ(scene.analysis.dynamics.time_step, defaults.dynamics.time_step);

  const OutputSettings output;
  EXPECT_DOUBLE_EQ(scene.output.interval, output.interval);
  EXPECT_EQ(scene.output.write_vtk, output.write_vtk);
  EXPECT_EQ(scene.output.vtk_points_per_element, output.vtk_points_per_element);
}

TEST(SceneLoaderTest, DynamicVariantHasItsSettings) {
  const Scene scene = ParseScene(
      Cantilever("analysis:\n  type: static\n  load_steps: 10\n",
                 "analysis: {type: dynamic, integrator: generalized_alpha, spectral_radius: 0.9, "
                 "time_step: 1.0e-3, end_time: 1.0}\n"));
  const DynamicSettings& dynamics = scene.analysis.dynamics;
  EXPECT_EQ(scene.analysis.type, AnalysisType::kDynamic);
  EXPECT_EQ(dynamics.integrator, IntegratorType::kGeneralizedAlpha);
  EXPECT_DOUBLE_EQ(dynamics.spectral_radius, 0.9);
  EXPECT_DOUBLE_EQ(dynamics.time_step, 1e-3);
  EXPECT_DOUBLE_EQ(dynamics.end_time, 1.0);
  const DynamicSettings defaults;
  EXPECT_DOUBLE_EQ(dynamics.min_time_step, defaults.min_time_step);
  EXPECT_EQ(dynamics.jacobian_update, defaults.jacobian_update);
  EXPECT_EQ(dynamics.newton.max_iterations, defaults.newton.max_iterations);
}

TEST(SceneLoaderTest, ReadsEveryAnalysisAndOutputKey) {
  const Scene scene = ParseScene(Cantilever("  load_steps: 10\n", R"(  load_steps: 4
  max_step_cuts: 0
  line_search: never
  integrator: explicit_verlet
  spectral_radius: 0
  time_step: 2.0e-4
  end_time: 3
  min_time_step: 1.0e-6
  jacobian_update: every_step
  max_iterations: 7
  relative_tolerance: 1.0e-5
  absolute_tolerance: 1.0e-9
  contact_couplings: {near_factor: 2, keep_updates: -1, max_stale_fraction: 0.25}
output: {interval: 0.01, vtk: false, vtk_points_per_element: 2}
)"));
  const AnalysisSettings& a = scene.analysis;
  EXPECT_EQ(a.type, AnalysisType::kStatic);
  EXPECT_EQ(a.statics.load_steps, 4);
  EXPECT_EQ(a.statics.max_step_cuts, 0);
  EXPECT_EQ(a.statics.newton.line_search, LineSearchMode::kNever);
  EXPECT_EQ(a.dynamics.newton.line_search, LineSearchMode::kNever);
  EXPECT_EQ(a.dynamics.integrator, IntegratorType::kExplicitVerlet);
  EXPECT_DOUBLE_EQ(a.dynamics.spectral_radius, 0.0);
  EXPECT_DOUBLE_EQ(a.dynamics.time_step, 2e-4);
  EXPECT_DOUBLE_EQ(a.dynamics.end_time, 3.0);
  EXPECT_DOUBLE_EQ(a.dynamics.min_time_step, 1e-6);
  EXPECT_EQ(a.dynamics.jacobian_update, JacobianUpdate::kEveryStep);
  EXPECT_DOUBLE_EQ(a.dynamics.contact_couplings.near_factor, 2.0);
  EXPECT_EQ(a.dynamics.contact_couplings.keep_updates, -1);
  EXPECT_DOUBLE_EQ(a.dynamics.contact_couplings.max_stale_fraction, 0.25);
  // Newton keys set both analyses.
  for (const NewtonSettings* newton : {&a.statics.newton, &a.dynamics.newton}) {
    EXPECT_EQ(newton->max_iterations, 7);
    EXPECT_DOUBLE_EQ(newton->relative_tolerance, 1e-5);
    EXPECT_DOUBLE_EQ(newton->absolute_tolerance, 1e-9);
  }
  EXPECT_DOUBLE_EQ(scene.output.interval, 0.01);
  EXPECT_FALSE(scene.output.write_vtk);
  EXPECT_EQ(scene.output.vtk_points_per_element, 2);
}

TEST(SceneLoaderTest, AnalysisAndOptionalSectionsMayBeLeftOut) {
  const std::string yaml = R"(materials: {m: {youngs_modulus: 1.0e9, density: 1000}}
sections: {s: {shape: circle, diameter: 0.002}}
cables: [{name: c, start: [0, 0, 0], end: [0, 0, -2], elements: 2, material: m, section: s}]
)";
  const Scene scene = ParseScene(yaml);
  EXPECT_EQ(scene.analysis.type, AnalysisType::kStatic);
  EXPECT_TRUE(scene.probes.empty());
  EXPECT_EQ(std::count(scene.model.fixed().begin(), scene.model.fixed().end(), true), 0);
}

TEST(SceneLoaderTest, ReadsCircleSectionDampingAndCableOptions) {
  const Scene scene = ParseScene(R"(gravity: [0, 0, -9.81]
materials:
  nylon: {youngs_modulus: 3.0e9, density: 1140, axial_damping_time: 0.01,
          bending_damping_time: 0.02}
sections:
  rope: {shape: circle, diameter: 0.004}
cables:
  - {name: a, start: [0, 0, 0], end: [2, 0, 0], elements: 4, material: nylon, section: rope,
     tension_only: true, axial_gauss_points: 2, bending_gauss_points: 5}
)");
  const double pi = std::acos(-1.0);
  const double area = pi * 0.004 * 0.004 / 4.0;
  const CableProperties& p = scene.model.cables()[0].properties;
  EXPECT_DOUBLE_EQ(p.axial_stiffness, 3.0e9 * area);
  EXPECT_DOUBLE_EQ(p.bending_stiffness, 3.0e9 * pi * std::pow(0.004, 4) / 64.0);
  EXPECT_DOUBLE_EQ(p.mass_per_length, 1140 * area);
  EXPECT_DOUBLE_EQ(p.axial_damping_time, 0.01);
  EXPECT_DOUBLE_EQ(p.bending_damping_time, 0.02);
  EXPECT_DOUBLE_EQ(p.radius, 0.002);
  EXPECT_TRUE(p.tension_only);
  EXPECT_EQ(p.axial_gauss_points, 2);
  EXPECT_EQ(p.bending_gauss_points, 5);
  EXPECT_EQ(scene.model.gravity(), Vector3d(0, 0, -9.81));
}

TEST(SceneLoaderTest, ReadsPointsConstraintsLoadsAndProbes) {
  // A cable name with a dot: the point string splits at the last one.
  const std::string yaml =
      Replace(Replace(Replace(Replace(kCantilever, "name: beam", "name: net.beam"), "beam.start",
                              "net.beam.start"),
                      "  - {type: point_force, at: beam.end, force: [0, 0, -333.333]}\n",
                      R"(  - {type: point_force, at: {cable: net.beam, s: 0.5}, force: [1, 2, 3]}
  - {type: point_moment, at: net.beam.end, moment: [0, 4, 0]}
  - {type: distributed, cable: net.beam, force_per_length: [0, 0, -5]}
)"),
              "  - {name: tip, quantity: position, at: beam.end}\n",
              R"(  - {name: mid, quantity: velocity, at: {cable: net.beam, s: 0.25}}
  - {name: e, quantity: energy}
)");
  const std::string with_fix = Replace(yaml, "  - {type: clamp, at: net.beam.start}\n",
                                       R"(  - {type: pin, at: net.beam.start}
  - {type: fix, at: {cable: net.beam, s: 0.5}, coordinates: [y, dz]}
)");
  const Scene scene = ParseScene(with_fix);
  const Model& model = scene.model;
  const std::vector<bool>& fixed = model.fixed();
  EXPECT_EQ(std::count(fixed.begin(), fixed.end(), true), 5);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(fixed[k]);  // pin: r of node 0
  EXPECT_TRUE(fixed[model.NodePositionDof(8) + 1]);   // fix y of node 8
  EXPECT_TRUE(fixed[model.NodeSlopeDof(8) + 2]);      // fix dz of node 8

  ASSERT_EQ(model.point_forces().size(), 1u);
  EXPECT_EQ(model.point_forces()[0].point.element, 8);
  EXPECT_DOUBLE_EQ(model.point_forces()[0].point.xi, 0.0);
  ASSERT_EQ(model.point_moments().size(), 1u);
  EXPECT_EQ(model.point_moments()[0].node, 16);
  EXPECT_EQ(model.point_moments()[0].moment, Vector3d(0, 4, 0));
  ASSERT_EQ(model.distributed_loads().size(), 1u);
  EXPECT_EQ(model.distributed_loads()[0].force_per_length, Vector3d(0, 0, -5));

  ASSERT_EQ(scene.probes.size(), 2u);
  EXPECT_EQ(scene.probes[0].quantity, ProbeQuantity::kVelocity);
  // The start of element 4, node 4 of 16.
  EXPECT_EQ(scene.probes[0].point.dof[0], model.elements()[4].dofs[0]);
  EXPECT_DOUBLE_EQ(scene.probes[0].point.weight[0], 1.0);
  EXPECT_EQ(scene.probes[1].name, "e");
  EXPECT_EQ(scene.probes[1].quantity, ProbeQuantity::kEnergy);
}

TEST(SceneLoaderTest, ReadsInitialVelocityAsVectorOrRigidMotion) {
  const Scene translation = ParseScene(
      Cantilever("    section: bar\n", "    section: bar\n    initial_velocity: [1, 2, 3]\n"));
  // The clamped node stays at rest; the tip moves with v.
  const VectorXd& v0 = translation.model.initial_velocities();
  EXPECT_EQ(v0.segment<3>(0), Vector3d::Zero());
  EXPECT_EQ(v0.segment<3>(translation.model.NodePositionDof(16)), Vector3d(1, 2, 3));

  const Scene rotation = ParseScene(Cantilever(
      "    section: bar\n",
      "    section: bar\n    initial_velocity: {angular: [0, 0, 2], center: [0.5, 0, 0]}\n"));
  // ṙ = ω × (r − c) at the tip r = (1, 0, 0): (0, 0, 2) × (0.5, 0, 0) = (0, 1, 0).
  const VectorXd& w0 = rotation.model.initial_velocities();
  EXPECT_TRUE(w0.segment<3>(rotation.model.NodePositionDof(16)).isApprox(Vector3d(0, 1, 0)));
  EXPECT_TRUE(w0.segment<3>(rotation.model.NodeSlopeDof(16)).isApprox(Vector3d(0, 2, 0)));
}

TEST(SceneLoaderTest, LoadsTheExampleFiles) {
  for (const char* name : {"cantilever_static.yaml", "cantilever_dynamic.yaml", "pendulum.yaml"}) {
    const std::filesystem::path file = SourceDir() / "examples" / name;
    SCOPED_TRACE(file.string());
    const Scene scene = LoadScene(file);
    EXPECT_EQ(scene.source, file.string());
    EXPECT_FALSE(scene.probes.empty());
  }
  // Every example a user may start from is a valid scene; study files (study_*.yaml,
  // docs/studies.md) are loaded by the study tests.
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourceDir() / "examples")) {
    if (entry.path().extension() != ".yaml" ||
        entry.path().filename().string().starts_with("study_"))
      continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(LoadScene(entry.path()));
    ++examples;
  }
  EXPECT_GE(examples, 7);
  const Scene statics = LoadScene(SourceDir() / "examples" / "cantilever_static.yaml");
  EXPECT_EQ(statics.model.num_dofs(), 102);
  EXPECT_EQ(statics.analysis.statics.load_steps, 10);
  const Scene dynamics = LoadScene(SourceDir() / "examples" / "cantilever_dynamic.yaml");
  EXPECT_EQ(dynamics.analysis.type, AnalysisType::kDynamic);
  EXPECT_DOUBLE_EQ(dynamics.analysis.dynamics.spectral_radius, 0.9);
}

TEST(SceneLoaderTest, ReportsAFileThatCannotBeOpened) {
  const std::filesystem::path missing = SourceDir() / "examples" / "no_such_scene.yaml";
  try {
    LoadScene(missing);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), missing.string() + ": cannot open scene file");
  }
}

// A scene with one mistake and the exact one-line message it must give.
struct BadScene {
  const char* name;
  std::string yaml;
  std::string message;
};

void PrintTo(const BadScene& scene, std::ostream* os) { *os << scene.name; }

class SceneLoaderErrorTest : public testing::TestWithParam<BadScene> {};

TEST_P(SceneLoaderErrorTest, GivesOneLineWithPositionAndKey) {
  const std::string message = ErrorOf(GetParam().yaml);
  EXPECT_EQ(message, GetParam().message);
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

const BadScene kBadScenes[] = {
    {"MalformedYaml", Cantilever("[0, 0, 0]\nmaterials", "[0, 0, 0\nmaterials"),
     "scene.yaml:2:10: invalid YAML: end of sequence flow not found"},
    {"BadIndentation", "gravity: [0, 0, 0]\n  materials: 1\n",
     "scene.yaml:2:3: invalid YAML: end of map not found"},
    // yaml-cpp quotes the character it cannot read: a control character or line break of a
    // binary file is written as \xNN, so the message stays one line.
    {"UnknownEscapeOfACarriageReturn", "a: \"x\\\ry\"\n",
     "scene.yaml:1:8: invalid YAML: unknown escape character: \\x0d"},
    {"UnknownEscapeOfAControlCharacter", "a: \"x\\\001y\"\n",
     "scene.yaml:1:8: invalid YAML: unknown escape character: \\x01"},
    {"EmptyScene", "# nothing\n",
     "scene.yaml:1:1: the scene is empty (expected a map with materials, sections and cables)"},
    {"SceneNotAMap", "- 1\n", "scene.yaml:1:1: expected a map, got a list of 1 item"},
    {"UnknownKeySuggests", Cantilever("youngs_modulus", "youngs_modulu"),
     "scene.yaml:3:11: unknown key 'youngs_modulu' in 'steel'; did you mean 'youngs_modulus'?"},
    {"UnknownTopLevelKeySuggests", Cantilever("gravity", "gravty"),
     "scene.yaml:1:1: unknown key 'gravty' at the top level; did you mean 'gravity'?"},
    {"UnknownKeyListsAllowed", Cantilever("    section: bar\n", "    section: bar\n    foo: 1\n"),
     "scene.yaml:13:5: unknown key 'foo' in 'cables[0]'; allowed keys: name, start, end, elements, "
     "material, section, tension_only, rope_smoothing_strain, bending, axial_gauss_points, "
     "bending_gauss_points, initial_velocity, breaking_force, element, orientation, continues"},
    {"DuplicateKey", Cantilever("    elements: 16\n", "    elements: 16\n    elements: 8\n"),
     "scene.yaml:11:5: duplicate key 'elements' (first given at line 10)"},
    {"MissingRequiredKey", Cantilever(", density: 7800", ""),
     "scene.yaml:3:10: missing required key 'density' in 'steel'"},
    {"MissingCables", "materials: {}\n",
     "scene.yaml:1:1: missing required key 'cables' at the top level"},
    {"NoCable", "materials: {}\ncables: []\n",
     "scene.yaml:2:9: expected a non-empty list, got an empty list (key 'cables')"},
    {"ElementsNotANumber", Cantilever("elements: 16", "elements: abc"),
     "scene.yaml:10:15: expected an integer ≥ 1, got 'abc' (key 'elements')"},
    {"ElementsNotAnInteger", Cantilever("elements: 16", "elements: 2.5"),
     "scene.yaml:10:15: expected an integer ≥ 1, got '2.5' (key 'elements')"},
    {"ElementsZero", Cantilever("elements: 16", "elements: 0"),
     "scene.yaml:10:15: expected an integer ≥ 1, got '0' (key 'elements')"},
    {"ElementsTooMany", Cantilever("elements: 16", "elements: 2000000000"),
     "scene.yaml:10:15: too many elements: at most 1000000 per cable, got 2000000000 "
     "(key 'elements')"},
    {"ElementsEmpty", Cantilever("elements: 16", "elements:"),
     "scene.yaml:10:5: expected an integer ≥ 1, got an empty value (key 'elements')"},
    {"VectorTooShort", Cantilever("start: [0, 0, 0]", "start: [0, 0]"),
     "scene.yaml:8:12: expected a list of 3 numbers [x, y, z], got a list of 2 items "
     "(key 'start')"},
    {"VectorNotAList", Cantilever("start: [0, 0, 0]", "start: \"x\""),
     "scene.yaml:8:12: expected a list of 3 numbers [x, y, z], got the string \"x\" "
     "(key 'start')"},
    {"VectorItemNotANumber", Cantilever("start: [0, 0, 0]", "start: [0, zero, 0]"),
     "scene.yaml:8:16: expected a number, got 'zero' (key 'start[1]')"},
    {"QuotedNumber", Cantilever("density: 7800", "density: \"7800\""),
     "scene.yaml:3:44: expected a number, got the string \"7800\" (key 'density')"},
    {"NotANumber", Cantilever("density: 7800", "density: .nan"),
     "scene.yaml:3:44: expected a finite number, got '.nan' (key 'density')"},
    {"Infinite", Cantilever("force: [0, 0, -333.333]", "force: [0, 0, -.inf]"),
     "scene.yaml:16:53: expected a finite number, got '-.inf' (key 'force[2]')"},
    {"YoungsModulusZero", Cantilever("2.0e11", "0"),
     "scene.yaml:3:27: expected a number > 0, got '0' (key 'youngs_modulus')"},
    {"YoungsModulusNegative", Cantilever("2.0e11", "-2.0e11"),
     "scene.yaml:3:27: expected a number > 0, got '-2.0e11' (key 'youngs_modulus')"},
    {"DensityZero", Cantilever("density: 7800", "density: 0"),
     "scene.yaml:3:44: expected a number > 0, got '0' (key 'density')"},
    {"NegativeDamping", Cantilever("density: 7800", "density: 7800, axial_damping_time: -1"),
     "scene.yaml:3:70: expected a number ≥ 0, got '-1' (key 'axial_damping_time')"},
    {"SectionWidthZero", Cantilever("width: 0.01", "width: 0"),
     "scene.yaml:5:34: expected a number > 0, got '0' (key 'width')"},
    {"SectionShapeUnknown", Cantilever("shape: rectangle", "shape: square"),
     "scene.yaml:5:16: expected one of circle, rectangle, general, got 'square' (key 'shape')"},
    {"CircleWithWidth", Cantilever("shape: rectangle", "shape: circle, diameter: 0.01"),
     "scene.yaml:5:40: unknown key 'width' in 'bar'; allowed keys: shape, diameter"},
    {"ZeroLengthCable", Cantilever("end: [1, 0, 0]", "end: [0, 0, 0]"),
     "scene.yaml:7:5: cable 'beam' has zero length (start equals end) (key 'cables[0]')"},
    {"GaussPointsOutOfRange",
     Cantilever("    section: bar\n", "    section: bar\n    axial_gauss_points: 9\n"),
     "scene.yaml:13:25: expected an integer in [1, 8], got '9' (key 'axial_gauss_points')"},
    {"TensionOnlyNotABool",
     Cantilever("    section: bar\n", "    section: bar\n    tension_only: yes please\n"),
     "scene.yaml:13:19: expected true or false, got 'yes please' (key 'tension_only')"},
    {"UnknownMaterialSuggests", Cantilever("material: steel", "material: stel"),
     "scene.yaml:11:15: no material named 'stel'; did you mean 'steel'? (key 'material')"},
    {"UnknownMaterialListsKnown", Cantilever("material: steel", "material: aluminium"),
     "scene.yaml:11:15: no material named 'aluminium'; known materials: steel "
     "(key 'material')"},
    {"UnknownSection", Cantilever("section: bar", "section: tube"),
     "scene.yaml:12:14: no section named 'tube'; known sections: bar (key 'section')"},
    {"UnknownCableInPoint", Cantilever("at: beam.start", "at: rope.start"),
     "scene.yaml:14:23: no cable named 'rope' (cables: beam) (key 'at')"},
    {"UnknownCableInProbe",
     Cantilever("quantity: position, at: beam.end", "quantity: position, at: rope.end"),
     "scene.yaml:18:41: no cable named 'rope' (cables: beam) (key 'at')"},
    {"UnknownCableInDistributedLoad",
     Cantilever("{type: point_force, at: beam.end, force: [0, 0, -333.333]}",
                "{type: distributed, cable: rope, force_per_length: [0, 0, -1]}"),
     "scene.yaml:16:32: no cable named 'rope' (cables: beam) (key 'cable')"},
    {"BadPointString", Cantilever("at: beam.end, force", "at: beam.middle, force"),
     "scene.yaml:16:29: expected a point CABLE.start, CABLE.end or {cable: NAME, s: FRACTION}, "
     "got 'beam.middle' (key 'at')"},
    {"PointWithoutDot", Cantilever("at: beam.end, force", "at: beam, force"),
     "scene.yaml:16:29: expected a point CABLE.start, CABLE.end or {cable: NAME, s: FRACTION}, "
     "got 'beam' (key 'at')"},
    {"PointFractionOutOfRange",
     Cantilever("at: beam.end, force", "at: {cable: beam, s: 1.5}, force"),
     "scene.yaml:16:46: expected a number in [0, 1], got '1.5' (key 's')"},
    {"ClampNotAtANode", Cantilever("at: beam.start", "at: {cable: beam, s: 0.3}"),
     "scene.yaml:14:23: s = 0.3 on cable 'beam' is not at a node (nodes are at multiples of "
     "1/16) (key 'at')"},
    {"ConstraintTypeSuggests", Cantilever("type: clamp", "type: clmap"),
     "scene.yaml:14:12: expected one of clamp, pin, fix, rotating_clamp, got 'clmap'; did you mean "
     "'clamp'? "
     "(key 'type')"},
    {"FixUnknownCoordinate",
     Cantilever("{type: clamp, at: beam.start}",
                "{type: fix, at: beam.start, coordinates: [x, w]}"),
     "scene.yaml:14:50: expected one of x, y, z, dx, dy, dz, got 'w' (key 'coordinates[1]')"},
    {"DuplicateCableName",
     Cantilever("constraints:\n",
                "  - {name: beam, start: [0, 0, 0], end: [0, 1, 0], elements: 1, "
                "material: steel, section: bar}\nconstraints:\n"),
     "scene.yaml:13:5: two cables are named 'beam' (key 'cables[1]')"},
    {"DuplicateProbeName",
     Cantilever("analysis:\n", "  - {name: tip, quantity: energy}\nanalysis:\n"),
     "scene.yaml:19:12: two probes are named 'tip' (the first at scene.yaml:18:12) (key 'name')"},
    {"EnergyProbeWithPoint", Cantilever("quantity: position", "quantity: energy"),
     "scene.yaml:18:39: an energy probe reads the whole system and takes no point (key 'at')"},
    {"ProbeWithoutPoint", Cantilever(", at: beam.end}", "}"),
     "scene.yaml:18:5: missing required key 'at' in 'probes[0]'"},
    {"AnalysisTypeMissing", Cantilever("  type: static\n", ""),
     "scene.yaml:20:3: missing required key 'type' in 'analysis'"},
    {"TimeStepZero", Cantilever("  load_steps: 10\n", "  time_step: 0\n"),
     "scene.yaml:21:14: expected a number > 0, got '0' (key 'time_step')"},
    {"SpectralRadiusAboveOne", Cantilever("  load_steps: 10\n", "  spectral_radius: 1.5\n"),
     "scene.yaml:21:20: expected a number in [0, 1], got '1.5' (key 'spectral_radius')"},
    {"MinTimeStepAboveTimeStep",
     Cantilever("  load_steps: 10\n", "  time_step: 1.0e-3\n  min_time_step: 0.01\n"),
     "scene.yaml:22:18: expected a number ≤ time_step (0.001), got '0.01' (key 'min_time_step')"},
    {"OutputUnknownKey", Cantilever() + "output: {vtk_point_per_element: 3}\n",
     "scene.yaml:22:10: unknown key 'vtk_point_per_element' in 'output'; did you mean "
     "'vtk_points_per_element'?"},
};

INSTANTIATE_TEST_SUITE_P(Scene, SceneLoaderErrorTest, testing::ValuesIn(kBadScenes),
                         [](const testing::TestParamInfo<BadScene>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace ancfnet
