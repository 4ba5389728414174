#include "ancfnet/run/run_modal.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/io/output_directory.hpp"
#include "ancfnet/io/vtk_writer.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

using Json = nlohmann::ordered_json;

// The configuration to linearise about.
VectorXd LinearisationPoint(const Scene& scene, Linearisation about) {
  State state = MakeInitialState(scene.model);
  if (about == Linearisation::kReference) return state.q;
  const SolveResult result = SolveStatic(
      scene.model, scene.analysis.statics, [](const State&, const EnergyAccount&) {}, &state);
  if (!result.completed)
    throw SolverError("the static equilibrium to linearise about failed: " + result.message, 0.0);
  return state.q;
}

// Largest extent of the configuration's positions (m), for scaling the shapes.
double ModelSize(const Model& model, const VectorXd& q) {
  Vector3d low = Vector3d::Constant(INFINITY), high = Vector3d::Constant(-INFINITY);
  const auto extend = [&](Index dof) {
    low = low.cwiseMin(q.segment<3>(dof));
    high = high.cwiseMax(q.segment<3>(dof));
  };
  for (Index node = 0; node < model.num_nodes(); ++node) extend(model.NodePositionDof(node));
  for (const PointMass& point : model.point_masses()) extend(point.dof);
  const double size = (high - low).maxCoeff();
  return size > 0.0 ? size : 1.0;
}

// Largest nodal displacement of a shape (position coordinates only).
double LargestDisplacement(const Model& model, const VectorXd& shape) {
  double largest = 0.0;
  for (Index node = 0; node < model.num_nodes(); ++node)
    largest = std::max(largest, shape.segment<3>(model.NodePositionDof(node)).norm());
  for (const PointMass& point : model.point_masses())
    largest = std::max(largest, shape.segment<3>(point.dof).norm());
  return largest;
}

void WriteModesJson(const std::filesystem::path& path, const ModalResult& modes,
                    Linearisation about, Index unknowns) {
  Json list = Json::array();
  for (Eigen::Index i = 0; i < modes.omega.size(); ++i) {
    const double f = modes.frequency_hz[i];
    const double zeta = modes.damping_ratio[i];
    list.push_back({{"mode", i + 1},
                    {"frequency_hz", f},
                    {"omega_rad_s", modes.omega[i]},
                    {"period_s", f > 0.0 ? Json(1.0 / f) : Json(nullptr)},
                    {"damping_ratio", std::isfinite(zeta) ? Json(zeta) : Json(nullptr)},
                    {"rigid", static_cast<bool>(modes.rigid[i])}});
  }
  const Json json = {{"about", about == Linearisation::kReference ? "reference" : "equilibrium"},
                     {"unknowns", unknowns},
                     {"modes", list}};
  std::ofstream file(path);
  file << json.dump(2) << '\n';
  if (!file) throw InputError(fmt::format("cannot write {}", path.string()));
}

}  // namespace

ModalResult RunModal(const Scene& scene, const ModalOptions& options) {
  CreateOutputDirectory(options.output_dir);
  const Model& model = scene.model;
  const VectorXd q = LinearisationPoint(scene, options.about);
  const ModalResult modes = CalcModes(model, q, options.settings);
  if (!modes.converged) throw SolverError(modes.message, 0.0);
  WriteModesJson(options.output_dir / "modes.json", modes, options.about,
                 DofMap::FreeCoordinates(model).num_unknowns());
  VtkSeriesWriter vtk(options.output_dir, "modes", scene.output.vtk_points_per_element);
  const double size = ModelSize(model, q);
  State frame = MakeInitialState(model);
  frame.v.setZero();
  for (Eigen::Index i = 0; i < modes.omega.size(); ++i) {
    const VectorXd shape = modes.shapes.col(i);
    const double largest = LargestDisplacement(model, shape);
    frame.t = static_cast<double>(i + 1);
    frame.q = q + (largest > 0.0 ? 0.1 * size / largest : 0.0) * shape;
    vtk.WriteFrame(model, frame);
  }
  return modes;
}

}  // namespace ancfnet
