#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/probe_csv_writer.hpp"
#include "ancfnet/io/summary_writer.hpp"
#include "ancfnet/io/test/output_test_files.hpp"
#include "ancfnet/io/vtk_writer.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

using test::MakeTestDirectory;
using test::ReadDataArray;
using test::ReadFile;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Two straight cables from the origin: "a" along x (1.5 m, 3 elements), "b" along y (1 m, 2
// elements). Steel, 4 mm diameter.
Model MakeModel(bool tension_only = false) {
  CableProperties properties =
      MakeCableProperties({.youngs_modulus = 2.0e11, .density = 7850.0}, MakeCircleSection(4e-3));
  properties.tension_only = tension_only;
  ModelBuilder builder;
  builder.AddCable({"a", Vector3d::Zero(), Vector3d(1.5, 0, 0), 3, properties});
  builder.AddCable({"b", Vector3d::Zero(), Vector3d(0, 1.0, 0), 2, properties});
  return builder.Build();
}

// A deformed, moving state (no symmetry, so a mix-up of coordinates shows).
State MakeDeformedState(const Model& model, double t) {
  State state = MakeInitialState(model);
  state.t = t;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    state.q[i] += 0.01 * std::sin(1.3 * static_cast<double>(i) + 0.2);
    state.v[i] = 0.5 * std::cos(0.7 * static_cast<double>(i));
  }
  return state;
}

EnergyAccount MakeEnergy() {
  return {.kinetic = 1.25, .strain = 0.5, .gravity = -3.0, .work = 0.125, .dissipated = 1e-3};
}

std::vector<Probe> MakeProbes(const Model& model) {
  return {
      {"tip", ProbeQuantity::kPosition, model.LocateMaterialPoint(model.LocateCablePoint(0, 1.0))},
      {"mid", ProbeQuantity::kVelocity, model.LocateMaterialPoint(model.LocateCablePoint(1, 0.3))},
      {"e", ProbeQuantity::kEnergy, {}}};
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::vector<double> ParseCsvRow(const std::string& line) {
  std::vector<double> values;
  std::istringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) values.push_back(std::stod(field));
  return values;
}

TEST(ProbeCsvWriter, WritesHeaderAndFullPrecisionRows) {
  const Model model = MakeModel();
  const std::vector<Probe> probes = MakeProbes(model);
  const std::filesystem::path path = MakeTestDirectory() / "probes.csv";
  const State state0 = MakeDeformedState(model, 0.0);
  const State state1 = MakeDeformedState(model, 0.1);
  const EnergyAccount energy = MakeEnergy();
  {
    ProbeCsvWriter writer(path, probes);
    writer.Append(model, state0, energy, {});
    writer.Append(model, state1, energy, {});
  }
  const std::vector<std::string> lines = SplitLines(ReadFile(path));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "time,tip.x,tip.y,tip.z,mid.vx,mid.vy,mid.vz,"
            "e.kinetic,e.strain,e.gravity,e.work,e.dissipated");
  const std::vector<double> row = ParseCsvRow(lines[2]);
  ASSERT_EQ(row.size(), 12u);
  EXPECT_EQ(row[0], 0.1);
  const Vector3d tip = Model::Locate(probes[0].point, state1.q);
  const Vector3d mid = Model::Locate(probes[1].point, state1.v);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(row[1 + i], tip[i]);  // bit-exact: the text reads back to the same double
    EXPECT_EQ(row[4 + i], mid[i]);
  }
  EXPECT_EQ(row[7], energy.kinetic);
  EXPECT_EQ(row[9], energy.gravity);
  EXPECT_EQ(row[11], energy.dissipated);
}

TEST(ProbeCsvWriter, RefusesNonFiniteValuesWithoutWritingTheRow) {
  const Model model = MakeModel();
  const std::vector<Probe> probes = MakeProbes(model);
  const std::filesystem::path path = MakeTestDirectory() / "probes.csv";
  ProbeCsvWriter writer(path, probes);
  writer.Append(model, MakeDeformedState(model, 0.0), MakeEnergy(), {});

  State bad = MakeDeformedState(model, 0.25);
  bad.q[model.NodePositionDof(model.LocateCableNode(0, 1.0)) + 1] = kNaN;  // tip.y
  try {
    writer.Append(model, bad, MakeEnergy(), {});
    FAIL() << "no SolverError";
  } catch (const SolverError& error) {
    EXPECT_STREQ(error.what(), "non-finite value in probe column tip.y");
    EXPECT_EQ(error.time(), 0.25);
  }
  EnergyAccount infinite = MakeEnergy();
  infinite.work = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writer.Append(model, MakeDeformedState(model, 0.5), infinite, {}), SolverError);

  EXPECT_EQ(SplitLines(ReadFile(path)).size(), 2u);  // header and the first row only
}

TEST(ProbeCsvWriter, UnwritablePathIsAnInputError) {
  const Model model = MakeModel();
  EXPECT_THROW(ProbeCsvWriter(MakeTestDirectory() / "missing" / "probes.csv", MakeProbes(model)),
               InputError);
}

Vector3d PointAt(const std::vector<double>& points, Index i) {
  return {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
}

Vector3d NodePosition(const Model& model, const State& state, Index node) {
  return state.q.segment<3>(model.NodePositionDof(node));
}

TEST(VtkSeriesWriter, WritesPolylinesThroughTheNodesAndTheCollection) {
  const Model model = MakeModel();
  const std::filesystem::path dir = MakeTestDirectory() / "vtk";  // created by the writer
  VtkSeriesWriter writer(dir, "cables", 4);
  const State state0 = MakeDeformedState(model, 0.0);
  const State state1 = MakeDeformedState(model, 0.5);
  writer.WriteFrame(model, state0);
  writer.WriteFrame(model, state1);
  EXPECT_EQ(writer.num_frames(), 2);
  ASSERT_TRUE(std::filesystem::exists(dir / "cables_000000.vtp"));
  ASSERT_TRUE(std::filesystem::exists(dir / "cables_000001.vtp"));

  const std::string xml = ReadFile(dir / "cables_000001.vtp");
  const Index num_points = (3 * 4 + 1) + (2 * 4 + 1);
  EXPECT_NE(xml.find(fmt::format("NumberOfPoints=\"{}\"", num_points)), std::string::npos);
  EXPECT_NE(xml.find("NumberOfLines=\"2\""), std::string::npos);
  const std::vector<double> points = ReadDataArray(xml, "position");
  ASSERT_EQ(static_cast<Index>(points.size()), 3 * num_points);
  EXPECT_EQ(ReadDataArray(xml, "velocity").size(), points.size());
  EXPECT_EQ(static_cast<Index>(ReadDataArray(xml, "curvature").size()), num_points);
  EXPECT_EQ(ReadDataArray(xml, "offsets"), (std::vector<double>{13, 22}));
  const std::vector<double> connectivity = ReadDataArray(xml, "connectivity");
  ASSERT_EQ(static_cast<Index>(connectivity.size()), num_points);
  EXPECT_EQ(connectivity.back(), num_points - 1);

  // Cable a: nodes 0..3 at points 0, 4, 8, 12; cable b: nodes 4..6 at points 13, 17, 21.
  const Cable& b = model.cables()[1];
  EXPECT_TRUE(PointAt(points, 0).isApprox(NodePosition(model, state1, 0)));
  EXPECT_TRUE(PointAt(points, 4).isApprox(NodePosition(model, state1, 1)));
  EXPECT_TRUE(PointAt(points, 12).isApprox(NodePosition(model, state1, 3)));
  EXPECT_TRUE(PointAt(points, 13).isApprox(NodePosition(model, state1, b.first_node)));
  EXPECT_TRUE(PointAt(points, 21).isApprox(NodePosition(model, state1, b.first_node + 2)));
  // An interior sample follows the Hermite interpolation.
  EXPECT_TRUE(PointAt(points, 6).isApprox(model.Interpolate({1, 0.5}, state1.q)));

  const std::string pvd = ReadFile(dir / "cables.pvd");
  const std::regex data_set("<DataSet timestep=\"([^\"]*)\"[^>]*file=\"([^\"]*)\"");
  std::vector<std::pair<double, std::string>> frames;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), data_set);
       it != std::sregex_iterator(); ++it)
    frames.emplace_back(std::stod((*it)[1]), (*it)[2]);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0], std::make_pair(0.0, std::string("cables_000000.vtp")));
  EXPECT_EQ(frames[1], std::make_pair(0.5, std::string("cables_000001.vtp")));
  EXPECT_FALSE(std::filesystem::exists(dir / "cables.pvd.tmp"));
}

TEST(VtkSeriesWriter, DrawsABodyFrameAfterTheCables) {
  CableProperties properties =
      MakeCableProperties({.youngs_modulus = 2.0e11, .density = 7850.0}, MakeCircleSection(4e-3));
  ModelBuilder builder;
  builder.AddCable({"a", Vector3d::Zero(), Vector3d(1.5, 0, 0), 3, properties});
  // J = diag(1, 1, 1) for 3 kg: axes √(3/3) = 1 m long; turned 90° about z.
  builder.AddRigidBody(
      {.name = "target",
       .mass = 3.0,
       .inertia = Matrix3d::Identity(),
       .position = Vector3d(0, 0, 2),
       .orientation = Matrix3d(Eigen::AngleAxisd(1.5707963267948966, Vector3d::UnitZ())),
       .velocity = Vector3d(1, 0, 0),
       .angular_velocity = Vector3d(0, 0, 2)});
  const Model model = builder.Build();
  const std::filesystem::path dir = MakeTestDirectory() / "vtk_body";
  VtkSeriesWriter writer(dir, "cables", 2);
  writer.WriteFrame(model, MakeInitialState(model));
  const std::string xml = ReadFile(writer.FramePath(0));
  EXPECT_NE(xml.find("NumberOfPoints=\"11\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfLines=\"4\""), std::string::npos);
  EXPECT_EQ(ReadDataArray(xml, "offsets"), (std::vector<double>{7, 9, 11, 13}));
  const std::vector<double> connectivity = ReadDataArray(xml, "connectivity");
  EXPECT_EQ(std::vector<double>(connectivity.begin() + 7, connectivity.end()),
            (std::vector<double>{7, 8, 7, 9, 7, 10}));
  const std::vector<double> points = ReadDataArray(xml, "position");
  EXPECT_TRUE(PointAt(points, 7).isApprox(Vector3d(0, 0, 2)));
  EXPECT_TRUE(PointAt(points, 8).isApprox(Vector3d(0, 1, 2)));  // body x along world y
  // Tip of body x: ẋ + R (ω × e_x) = (1, 0, 0) + R (0, 2, 0) = (1 − 2, 0, 0).
  const std::vector<double> velocity = ReadDataArray(xml, "velocity");
  EXPECT_TRUE(PointAt(velocity, 8).isApprox(Vector3d(-1, 0, 0)));
}

// Stretches (λ > 1) or compresses (λ < 1) both straight cables uniformly.
std::string WriteUniformlyStretchedFrame(bool tension_only, double stretch,
                                         const std::filesystem::path& dir) {
  const Model model = MakeModel(tension_only);
  State state = MakeInitialState(model);
  state.q *= stretch;  // the cables start at the origin, so r → λ r and r' → λ r'
  VtkSeriesWriter writer(dir, "frame", 3);
  writer.WriteFrame(model, state);
  return ReadFile(writer.FramePath(0));
}

// The section force of a uniformly stretched cable is N r' = EA ε λ t, so its tension is EA ε λ.
TEST(VtkSeriesWriter, TensionOfAStretchedCableIsItsSectionForce) {
  const Model model = MakeModel();
  const double ea = model.elements()[0].parameters.axial_stiffness;
  const double stretch = 1.01;
  const double strain = 0.5 * (stretch * stretch - 1.0);
  const double expected = ea * strain * stretch;
  const std::string xml = WriteUniformlyStretchedFrame(false, stretch, MakeTestDirectory());
  const std::vector<double> tension = ReadDataArray(xml, "tension");
  const std::vector<double> axial = ReadDataArray(xml, "axial_strain");
  ASSERT_EQ(tension.size(), 3u * 3 + 1 + 2 * 3 + 1);
  ASSERT_EQ(axial.size(), tension.size());
  for (std::size_t i = 0; i < tension.size(); ++i) {
    EXPECT_NEAR(axial[i], strain, 1e-12) << i;
    EXPECT_NEAR(tension[i], expected, 1e-9 * expected) << i;
  }
  for (double kappa : ReadDataArray(xml, "curvature")) EXPECT_NEAR(kappa, 0.0, 1e-12);
}

TEST(VtkSeriesWriter, CompressedRopeCarriesNoTension) {
  const std::string xml = WriteUniformlyStretchedFrame(true, 0.99, MakeTestDirectory());
  for (double axial : ReadDataArray(xml, "axial_strain")) EXPECT_LT(axial, 0.0);
  for (double tension : ReadDataArray(xml, "tension")) EXPECT_EQ(tension, 0.0);
}

TEST(VtkSeriesWriter, RefusesANonFiniteFrameAndWritesNothing) {
  const Model model = MakeModel();
  const std::filesystem::path dir = MakeTestDirectory();
  VtkSeriesWriter writer(dir, "cables", 2);
  writer.WriteFrame(model, MakeDeformedState(model, 0.0));
  State state = MakeDeformedState(model, 0.25);
  state.v[7] = kNaN;
  try {
    writer.WriteFrame(model, state);
    FAIL() << "no error";
  } catch (const SolverError& error) {
    EXPECT_EQ(error.time(), 0.25);
    EXPECT_NE(std::string(error.what()).find("non-finite velocity"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(writer.num_frames(), 1);
  EXPECT_FALSE(std::filesystem::exists(writer.FramePath(1)));
  EXPECT_EQ(ReadFile(writer.collection_path()).find("cables_000001"), std::string::npos);
}

TEST(VtkSeriesWriter, RejectsFewerThanOnePointPerElement) {
  EXPECT_THROW(VtkSeriesWriter(MakeTestDirectory(), "cables", 0), InputError);
}

RunSummary MakeSummary() {
  RunSummary summary;
  summary.analysis = "dynamic";
  summary.end_time = 1.5;
  summary.steps = 150;
  summary.newton_iterations = 420;
  summary.jacobian_updates = 37;
  summary.pattern_rebuilds = 5;
  summary.step_cuts = 2;
  summary.wall_time_s = 0.75;
  summary.energy = MakeEnergy();
  return summary;
}

TEST(SummaryWriter, WritesCountersEnergiesAndFinalProbeValues) {
  const Model model = MakeModel();
  const std::vector<Probe> probes = MakeProbes(model);
  const State state = MakeDeformedState(model, 1.5);
  const RunSummary summary = MakeSummary();
  const std::filesystem::path path = MakeTestDirectory() / "summary.json";
  WriteSummaryJson(path, summary, probes, model, state, {});

  const std::string text = ReadFile(path);
  EXPECT_NE(text.find("\n  \"status\": \"completed\""), std::string::npos) << "indent 2";
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json["status"], "completed");
  EXPECT_EQ(json["message"], "");
  EXPECT_EQ(json["analysis"], "dynamic");
  EXPECT_EQ(json["time"], 1.5);
  EXPECT_EQ(json["steps"], 150);
  EXPECT_EQ(json["newton_iterations"], 420);
  EXPECT_EQ(json["jacobian_updates"], 37);
  EXPECT_EQ(json["pattern_rebuilds"], 5);
  EXPECT_EQ(json["step_cuts"], 2);
  EXPECT_EQ(json["wall_time_s"], 0.75);
  const nlohmann::json& energy = json["energy"];
  EXPECT_EQ(energy["kinetic"], 1.25);
  EXPECT_EQ(energy["strain"], 0.5);
  EXPECT_EQ(energy["gravity"], -3.0);
  EXPECT_EQ(energy["work"], 0.125);
  EXPECT_EQ(energy["dissipated"], 1e-3);
  EXPECT_EQ(energy["balance"], summary.energy.Balance());

  const Vector3d tip = Model::Locate(probes[0].point, state.q);
  const Vector3d mid = Model::Locate(probes[1].point, state.v);
  const nlohmann::json& values = json["probes"];
  ASSERT_EQ(values.size(), 3u);
  ASSERT_EQ(values["tip"]["position"].size(), 3u);
  ASSERT_EQ(values["mid"]["velocity"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(values["tip"]["position"][i], tip[i]);
    EXPECT_EQ(values["mid"]["velocity"][i], mid[i]);
  }
  EXPECT_EQ(values["e"]["energy"]["kinetic"], 1.25);
  EXPECT_EQ(values["e"]["energy"]["dissipated"], 1e-3);
  EXPECT_EQ(values["e"]["energy"].size(), 5u);
}

TEST(SummaryWriter, FailedRunWritesNullForNonFiniteNumbers) {
  const Model model = MakeModel();
  State state = MakeDeformedState(model, 0.3);
  state.q[model.NodePositionDof(model.LocateCableNode(0, 1.0))] = kNaN;  // tip.x
  RunSummary summary = MakeSummary();
  summary.completed = false;
  summary.message = "Newton did not converge at t = 0.3 s";
  summary.energy.kinetic = std::numeric_limits<double>::infinity();
  const std::filesystem::path path = MakeTestDirectory() / "summary.json";
  WriteSummaryJson(path, summary, MakeProbes(model), model, state, {});

  const std::string text = ReadFile(path);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("inf"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json["status"], "failed");
  EXPECT_EQ(json["message"], summary.message);
  EXPECT_TRUE(json["energy"]["kinetic"].is_null());
  EXPECT_TRUE(json["energy"]["balance"].is_null());
  EXPECT_EQ(json["energy"]["strain"], 0.5);
  EXPECT_TRUE(json["probes"]["tip"]["position"][0].is_null());
  EXPECT_TRUE(json["probes"]["e"]["energy"]["kinetic"].is_null());
}

TEST(SummaryWriter, UnwritablePathIsAnInputError) {
  const Model model = MakeModel();
  EXPECT_THROW(WriteSummaryJson(MakeTestDirectory() / "missing" / "summary.json", MakeSummary(), {},
                                model, MakeInitialState(model), {}),
               InputError);
}

}  // namespace
}  // namespace ancfnet
