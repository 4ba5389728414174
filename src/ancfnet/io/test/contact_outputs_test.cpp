// The contact outputs: the contact probe read from YAML (and its errors), its values for a bead
// pressed into a box against hand-computed forces and moments, the contact VTK frames, and a
// run whose contact frames hold as many points as the probe counts contacts.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/io/contact_vtk_writer.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/run/run_scene.hpp"

namespace ancfnet {
namespace {

// A bead of radius 1 cm pressed 0.2 mm into the top face (z = 0.5) of a box while sliding along x,
// and a 0.2 m rope of 2 elements (4 inspection spheres each) lying 10 µm deep in the plane z = 0.
constexpr const char* kScene = R"(gravity: [0, 0, -9.81]
materials:
  nylon: {youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-3}
sections:
  rope: {shape: circle, diameter: 0.002}
point_masses:
  - {name: bead, mass: 0.1, position: [0.3, 0.2, 0.5098], velocity: [0.5, 0, -0.1]}
cables:
  - {name: rope, start: [0, 0, 0.00099], end: [0.2, 0, 0.00099], elements: 2, material: nylon,
     section: rope}
contact:
  law: {type: linear, stiffness: 1.0e4, damping: 10}
  friction: {type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-3}
  points_per_element: 4
  point_mass_radius: 0.01
  targets:
    - {name: floor, type: box, center: [0, 0, 0.4], half_extents: [1, 1, 0.1]}
    - {name: ground, type: plane, point: [0, 0, 0], normal: [0, 0, 1]}
probes:
  - {name: on_floor, quantity: contact, target: floor}
  - {name: all, quantity: contact}
analysis:
  type: dynamic
  time_step: 1.0e-3
  end_time: 0.01
output:
  interval: 0.005
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

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

int NumberOfPoints(const std::string& xml) {
  std::smatch match;
  EXPECT_TRUE(std::regex_search(xml, match, std::regex("NumberOfPoints=\"(\\d+)\"")));
  return std::stoi(match[1]);
}

std::filesystem::path MakeTestDirectory() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("ancfnet_contact_outputs_" +
       std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(ContactProbe, ReadsTargetAndNamesColumns) {
  const Scene scene = ParseScene(kScene, "scene.yaml");
  ASSERT_EQ(scene.probes.size(), 2u);
  EXPECT_EQ(scene.probes[0].quantity, ProbeQuantity::kContact);
  EXPECT_EQ(scene.probes[0].target, 0);
  EXPECT_EQ(scene.probes[1].target, -1);
  EXPECT_EQ(ProbeColumns(scene.probes[0]),
            (std::vector<std::string>{"on_floor.active", "on_floor.normal_force",
                                      "on_floor.friction_force", "on_floor.fx", "on_floor.fy",
                                      "on_floor.fz", "on_floor.mx", "on_floor.my", "on_floor.mz",
                                      "on_floor.max_penetration"}));
}

TEST(ContactProbe, BadTargetOrNoContactIsAnInputError) {
  const std::string unknown = ErrorOf(Replace(kScene, "target: floor", "target: flor"));
  EXPECT_NE(unknown.find("no contact target named 'flor'; did you mean 'floor'?"),
            std::string::npos)
      << unknown;
  const std::string extra = ErrorOf(Replace(kScene, "target: floor", "target: floor, net: x"));
  EXPECT_NE(extra.find("net"), std::string::npos) << extra;
  std::string no_contact = kScene;
  no_contact.erase(no_contact.find("contact:\n"),
                   no_contact.find("probes:") - no_contact.find("contact:\n"));
  no_contact = Replace(no_contact, ", target: floor", "");
  const std::string message = ErrorOf(no_contact);
  EXPECT_NE(message.find("a contact probe needs contact targets"), std::string::npos) << message;
}

TEST(ContactProbe, ForceAndMomentOnTheTarget) {
  const Scene scene = ParseScene(kScene, "scene.yaml");
  const Model& model = scene.model;
  const State state = MakeInitialState(model);
  std::vector<ContactPoint> contacts;
  TargetContact(model).CollectContacts(state.q, state.v, state.contact_history, &contacts);
  ASSERT_EQ(contacts.size(), 9u);  // the bead on the floor, 8 rope spheres on the ground
  std::vector<double> values;
  EvaluateProbe(scene.probes[0], model, state, {}, contacts, &values);
  ASSERT_EQ(values.size(), 10u);
  // F_n = k δ + c δ̇ with δ = 0.2 mm, δ̇ = 0.1 m/s; friction −μ F_n tanh(0.5/10⁻³) along x.
  const double normal = 1e4 * 2e-4 + 10 * 0.1;
  const double friction = 0.3 * normal * std::tanh(500.0);
  EXPECT_EQ(values[0], 1.0);
  EXPECT_NEAR(values[1], normal, 1e-9);
  EXPECT_NEAR(values[2], friction, 1e-9);
  // On the floor: −f = (μ F_n, 0, −F_n) at p = (0.3, 0.2, 0.5), moment about the box's centre
  // c = (0, 0, 0.4): (p − c) × (−f) = (0.3, 0.2, 0.1) × (μF, 0, −F) = (−0.2 F, 0.1 μF + 0.3 F,
  // −0.2 μF).
  const Vector3d force(friction, 0, -normal);
  const Vector3d moment(-0.2 * normal, 0.1 * friction + 0.3 * normal, -0.2 * friction);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(values[3 + i], force[i], 1e-9) << i;
    EXPECT_NEAR(values[6 + i], moment[i], 1e-9) << i;
  }
  EXPECT_NEAR(values[9], 2e-4, 1e-12);

  // All contacts: nine, moment about the origin, the rope's spheres 10 µm deep.
  values.clear();
  EvaluateProbe(scene.probes[1], model, state, {}, contacts, &values);
  EXPECT_EQ(values[0], 9.0);
  EXPECT_NEAR(values[1], normal + 8 * 1e4 * 1e-5, 1e-9);
  EXPECT_NEAR(values[5], -values[1], 1e-9);
  EXPECT_NEAR(values[9], 2e-4, 1e-12);
}

TEST(ContactVtkWriter, WritesOneVertexPerContactAndTheCollection) {
  const std::filesystem::path dir = MakeTestDirectory();
  ContactVtkWriter writer(dir, "contacts");
  ContactPoint a, b;
  a.point_W = Vector3d(1, 2, 3);
  a.normal_force = 4.5;
  a.force_W = Vector3d(0.5, 0, 4.5);
  a.penetration = 1e-4;
  b.point_W = Vector3d(-1, 0, 0);
  b.normal_W = Vector3d(-1, 0, 0);
  writer.WriteFrame(0.0, {a, b});
  writer.WriteFrame(0.25, {});
  EXPECT_EQ(writer.num_frames(), 2);
  const std::string first = ReadFile(dir / "contacts_000000.vtp");
  EXPECT_EQ(NumberOfPoints(first), 2);
  EXPECT_NE(first.find("NumberOfVerts=\"2\""), std::string::npos);
  EXPECT_NE(first.find("          1 2 3\n"), std::string::npos);
  EXPECT_NE(first.find("          0.5 0 4.5\n"), std::string::npos);
  EXPECT_NE(first.find("Name=\"penetration\""), std::string::npos);
  EXPECT_EQ(NumberOfPoints(ReadFile(dir / "contacts_000001.vtp")), 0);
  const std::string pvd = ReadFile(dir / "contacts.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.25\" group=\"\" part=\"0\" file=\"contacts_000001.vtp\""),
            std::string::npos);

  ContactPoint bad = a;
  bad.normal_force = std::nan("");
  EXPECT_THROW(writer.WriteFrame(0.5, {bad}), SolverError);
  EXPECT_EQ(writer.num_frames(), 2);
}

TEST(RunScene, ContactFramesHoldTheActiveContacts) {
  const Scene scene = ParseScene(kScene, "scene.yaml");
  const std::filesystem::path dir = MakeTestDirectory();
  RunOptions options;
  options.output_dir = dir;
  options.show_progress = false;
  const RunSummary summary = RunScene(scene, options);
  ASSERT_TRUE(summary.completed) << summary.message;
  ASSERT_EQ(summary.outputs, 3);
  // probes.csv: time, on_floor (10 columns), all (10 columns): all.active is column 11.
  std::ifstream csv(dir / "probes.csv");
  std::string line;
  std::getline(csv, line);
  for (int frame = 0; frame < 3; ++frame) {
    ASSERT_TRUE(std::getline(csv, line));
    std::stringstream row(line);
    std::string cell;
    for (int column = 0; column <= 11; ++column) std::getline(row, cell, ',');
    const int active = std::stoi(cell);
    if (frame == 0) {
      EXPECT_EQ(active, 9);
    }
    EXPECT_GE(active, 1);
    EXPECT_EQ(NumberOfPoints(ReadFile(dir / fmt::format("contacts_{:06d}.vtp", frame))), active)
        << "frame " << frame;
  }
  EXPECT_NE(ReadFile(dir / "contacts.pvd").find("contacts_000002.vtp"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "contacts_000003.vtp"));
}

}  // namespace
}  // namespace ancfnet
