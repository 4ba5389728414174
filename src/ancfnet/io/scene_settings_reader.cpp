#include "ancfnet/io/scene_settings_reader.hpp"

#include <fmt/format.h>

#include <optional>

namespace ancfnet {
namespace {

// Newton keys, applied to `newton` (over its own defaults) when given.
void ReadNewtonSettings(const YamlMap& map, NewtonSettings* newton) {
  if (auto v = map.Find("max_iterations")) newton->max_iterations = v->AsInt(1);
  if (auto v = map.Find("relative_tolerance")) newton->relative_tolerance = v->AsPositive();
  if (auto v = map.Find("absolute_tolerance")) newton->absolute_tolerance = v->AsPositive();
  if (auto v = map.Find("energy_tolerance")) newton->energy_tolerance = v->AsPositive();
  if (auto v = map.Find("line_search")) {
    newton->line_search = v->AsEnum<LineSearchMode>({{"auto", LineSearchMode::kAuto},
                                                     {"always", LineSearchMode::kAlways},
                                                     {"never", LineSearchMode::kNever}});
  }
}

void ReadStaticSettings(const YamlMap& map, StaticSettings* statics) {
  if (auto v = map.Find("load_steps")) statics->load_steps = v->AsInt(1);
  if (auto v = map.Find("max_step_cuts")) statics->max_step_cuts = v->AsInt(0);
  ReadNewtonSettings(map, &statics->newton);
}

void ReadDynamicSettings(const YamlMap& map, DynamicSettings* dynamics) {
  if (auto v = map.Find("integrator")) {
    dynamics->integrator =
        v->AsEnum<IntegratorType>({{"generalized_alpha", IntegratorType::kGeneralizedAlpha},
                                   {"midpoint", IntegratorType::kImplicitMidpoint},
                                   {"explicit_verlet", IntegratorType::kExplicitVerlet}});
  }
  if (auto v = map.Find("spectral_radius")) dynamics->spectral_radius = v->AsNumberIn(0.0, 1.0);
  if (auto v = map.Find("time_step")) dynamics->time_step = v->AsPositive();
  if (auto v = map.Find("end_time")) dynamics->end_time = v->AsPositive();
  // A run of more steps than this would not end in any sensible time (h = 1e-300 s once hung).
  constexpr double kMaxSteps = 1e9;
  if (const double steps = dynamics->end_time / dynamics->time_step; steps > kMaxSteps) {
    const std::optional<YamlValue> where = map.Find("time_step");
    const std::string why = fmt::format(
        "time_step {} s to end_time {} s is {:.3g} steps; at most {:.0e} are accepted",
        dynamics->time_step, dynamics->end_time, steps, kMaxSteps);
    if (where) where->Fail(why);
    map.Get("end_time").Fail(why);
  }
  if (auto v = map.Find("min_time_step")) {
    dynamics->min_time_step = v->AsPositive();
    if (dynamics->min_time_step > dynamics->time_step)
      v->FailExpected(fmt::format("a number ≤ time_step ({})", dynamics->time_step));
  }
  if (auto v = map.Find("energy_drift")) dynamics->energy_drift = v->AsNumberIn(0.0, 1.0);
  if (auto v = map.Find("jacobian_update")) {
    dynamics->jacobian_update =
        v->AsEnum<JacobianUpdate>({{"every_iteration", JacobianUpdate::kEveryIteration},
                                   {"every_step", JacobianUpdate::kEveryStep},
                                   {"adaptive", JacobianUpdate::kAdaptive}});
  }
  ReadNewtonSettings(map, &dynamics->newton);
  if (auto v = map.Find("contact_couplings")) {
    const YamlMap couplings = v->AsMap();
    couplings.CheckKeys({"near_factor", "keep_updates", "max_stale_fraction"});
    ContactCouplingSettings& c = dynamics->contact_couplings;
    if (auto w = couplings.Find("near_factor")) c.near_factor = w->AsNumberIn(1.0, 100.0);
    if (auto w = couplings.Find("keep_updates")) c.keep_updates = w->AsInt(-1);
    if (auto w = couplings.Find("max_stale_fraction"))
      c.max_stale_fraction = w->AsNumberIn(0.0, 1.0);
  }
}

}  // namespace

AnalysisSettings ReadAnalysisSettings(const YamlValue& analysis) {
  const YamlMap map = analysis.AsMap();
  map.CheckKeys({"type", "load_steps", "max_step_cuts", "line_search", "integrator",
                 "spectral_radius", "time_step", "end_time", "min_time_step", "energy_drift",
                 "jacobian_update", "max_iterations", "relative_tolerance", "absolute_tolerance",
                 "energy_tolerance", "contact_couplings"});
  AnalysisSettings settings;
  settings.type = map.Get("type").AsEnum<AnalysisType>(
      {{"static", AnalysisType::kStatic}, {"dynamic", AnalysisType::kDynamic}});
  ReadStaticSettings(map, &settings.statics);
  ReadDynamicSettings(map, &settings.dynamics);
  return settings;
}

void CheckRunWork(const DynamicSettings& dynamics, Index unknowns, double max_unknown_steps,
                  const YamlValue& analysis) {
  const double steps = dynamics.end_time / dynamics.time_step;
  const double work = steps * static_cast<double>(unknowns);
  if (work <= max_unknown_steps) return;
  const YamlMap map = analysis.AsMap();
  const YamlValue where = map.Find("time_step") ? map.Get("time_step") : analysis;
  where.Fail(fmt::format(
      "{:.3g} steps (end_time {} s / time_step {} s) of {} unknowns are {:.3g} unknown-steps, "
      "above the limit of {:.0e} (10¹² take months on one core); check time_step and end_time, "
      "or run it anyway with --force",
      steps, dynamics.end_time, dynamics.time_step, unknowns, work, max_unknown_steps));
}

OutputSettings ReadOutputSettings(const YamlValue& output) {
  const YamlMap map = output.AsMap();
  map.CheckKeys({"interval", "vtk", "vtk_points_per_element"});
  OutputSettings settings;
  if (auto v = map.Find("interval")) settings.interval = v->AsNonNegative();
  if (auto v = map.Find("vtk")) settings.write_vtk = v->AsBool();
  if (auto v = map.Find("vtk_points_per_element"))
    settings.vtk_points_per_element = v->AsInt(1, 64);
  return settings;
}

}  // namespace ancfnet
