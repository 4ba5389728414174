#include "scene_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ancfnet {

void PrintSceneReport(const Scene& scene, std::FILE* out) {
  const Model& model = scene.model;
  const auto fixed = std::count(model.fixed().begin(), model.fixed().end(), true);
  fmt::print(out, "{}: valid scene\n", scene.source);
  for (const Cable& cable : model.cables())
    fmt::print(out, "  cable {}: {} elements, length {:.6g} m, EA {:.6g} N, EI {:.6g} N m², "
               "ρA {:.6g} kg/m{}\n",
               cable.name, cable.num_elements, cable.length, cable.properties.axial_stiffness,
               cable.properties.bending_stiffness, cable.properties.mass_per_length,
               cable.properties.tension_only ? ", tension only" : "");
  fmt::print(out, "  {} coordinates, {} fixed, {} unknowns; total mass {:.6g} kg\n",
             model.num_dofs(), fixed, model.num_dofs() - fixed, model.total_mass());
  fmt::print(out, "  loads: {} point forces, {} point moments, {} distributed; gravity [{}, {}, {}]\n",
             model.point_forces().size(), model.point_moments().size(),
             model.distributed_loads().size(), model.gravity().x(), model.gravity().y(),
             model.gravity().z());
  fmt::print(out, "  {} probes\n", scene.probes.size());
  const AnalysisSettings& a = scene.analysis;
  if (a.type == AnalysisType::kStatic)
    fmt::print(out, "  analysis: static, {} load steps\n", a.statics.load_steps);
  else
    fmt::print(out, "  analysis: dynamic, {}, h = {:.6g} s to t = {:.6g} s\n",
               a.dynamics.integrator == IntegratorType::kGeneralizedAlpha
                   ? fmt::format("generalized-α (ρ∞ = {})", a.dynamics.spectral_radius)
                   : std::string("explicit Verlet"),
               a.dynamics.time_step, a.dynamics.end_time);
}

}  // namespace ancfnet
