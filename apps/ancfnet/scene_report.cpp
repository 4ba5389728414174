#include "scene_report.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <string>
#include <vector>

namespace ancfnet {
namespace {

std::string IntegratorDescription(const DynamicSettings& dynamics) {
  switch (dynamics.integrator) {
    case IntegratorType::kGeneralizedAlpha:
      return fmt::format("generalized-α (ρ∞ = {})", dynamics.spectral_radius);
    case IntegratorType::kImplicitMidpoint:
      return "implicit midpoint";
    case IntegratorType::kExplicitVerlet:
      return "explicit Verlet";
  }
  return "";
}

}  // namespace

void PrintSceneReport(const Scene& scene, std::FILE* out) {
  const Model& model = scene.model;
  const auto fixed = std::count(model.fixed().begin(), model.fixed().end(), true);
  fmt::print(out, "{}: valid scene\n", scene.source);
  // Threads of nets are summed up per net rather than listed.
  std::vector<bool> in_net(model.cables().size(), false);
  for (const Net& net : model.nets()) {
    double mass = 0.0;
    for (Index knot : net.knots) mass += model.point_masses()[knot].mass;
    fmt::print(out, "  net {}: {} knots ({:.6g} kg with the bullets), {} threads\n", net.name,
               net.knots.size(), mass, net.threads.size());
    for (Index thread : net.threads) in_net[thread] = true;
  }
  for (std::size_t c = 0; c < model.cables().size(); ++c) {
    if (in_net[c]) continue;
    const Cable& cable = model.cables()[c];
    fmt::print(out,
               "  cable {}: {} elements, length {:.6g} m, EA {:.6g} N, EI {:.6g} N m², "
               "ρA {:.6g} kg/m{}\n",
               cable.name, cable.num_elements, cable.length, cable.properties.axial_stiffness,
               cable.properties.bending_stiffness, cable.properties.mass_per_length,
               cable.properties.tension_only ? ", tension only" : "");
  }
  constexpr const char* kMotion[] = {"free", "fixed", "prescribed"};
  for (const RigidBody& body : model.rigid_bodies()) {
    const Vector3d moments = Eigen::SelfAdjointEigenSolver<Matrix3d>(body.inertia).eigenvalues();
    fmt::print(out, "  body {}: {:.6g} kg, principal moments [{:.6g}, {:.6g}, {:.6g}] kg m², {}\n",
               body.name, body.mass, moments[0], moments[1], moments[2],
               kMotion[static_cast<int>(body.motion)]);
  }
  if (!model.body_attachments().empty())
    fmt::print(out, "  {} body attachments\n", model.body_attachments().size());
  fmt::print(out, "  {} coordinates, {} fixed, {} unknowns; total mass {:.6g} kg\n",
             model.num_dofs(), fixed, model.num_dofs() - fixed, model.total_mass());
  fmt::print(
      out, "  loads: {} point forces, {} point moments, {} distributed; gravity [{}, {}, {}]\n",
      model.point_forces().size(), model.point_moments().size(), model.distributed_loads().size(),
      model.gravity().x(), model.gravity().y(), model.gravity().z());
  const DampingSpec& damping = model.damping();
  if (damping.rayleigh.alpha != 0.0 || damping.rayleigh.beta != 0.0)
    fmt::print(out, "  Rayleigh damping: α = {:.6g} 1/s, β = {:.6g} s\n", damping.rayleigh.alpha,
               damping.rayleigh.beta);
  if (damping.modal.num_modes > 0)
    fmt::print(out, "  modal damping of the {} lowest elastic modes\n", damping.modal.num_modes);
  fmt::print(out, "  {} probes\n", scene.probes.size());
  const AnalysisSettings& a = scene.analysis;
  if (a.type == AnalysisType::kStatic)
    fmt::print(out, "  analysis: static, {} load steps\n", a.statics.load_steps);
  else
    fmt::print(out, "  analysis: dynamic, {}, h = {:.6g} s to t = {:.6g} s\n",
               IntegratorDescription(a.dynamics), a.dynamics.time_step, a.dynamics.end_time);
}

}  // namespace ancfnet
