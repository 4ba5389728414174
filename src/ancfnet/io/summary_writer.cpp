#include "ancfnet/io/summary_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ancfnet/analysis/capture_metrics.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

using Json = nlohmann::ordered_json;

// A number, or null when it is NaN or infinite (JSON has no such values).
Json Number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json EnergyJson(const EnergyAccount& energy) {
  return {{"kinetic", Number(energy.kinetic)},       {"strain", Number(energy.strain)},
          {"gravity", Number(energy.gravity)},       {"work", Number(energy.work)},
          {"dissipated", Number(energy.dissipated)}, {"balance", Number(energy.Balance())}};
}

Json FailuresJson(const std::vector<FailureEvent>& failures) {
  Json list = Json::array();
  for (const FailureEvent& f : failures)
    list.push_back({{"time", Number(f.time)}, {"what", f.what}, {"tension", Number(f.tension)}});
  return list;
}

// A capture probe's metrics (analysis/capture_metrics.hpp) and its first contact time.
Json CaptureJson(const Probe& probe, const Model& model, const State& state,
                 const std::vector<ContactPoint>& contacts, const RunSummary& summary) {
  const CaptureMetrics m =
      CalcCaptureMetrics(model, state, probe.net, probe.target, contacts, probe.reference_area);
  const auto first = summary.first_contact_times.find(probe.name);
  // The peaks over the run; a run that observed none (e.g. a summary written without a run)
  // has only the tensions at `state`.
  const auto observed = summary.peak_tensions.find(probe.name);
  const PeakTensions peak =
      observed == summary.peak_tensions.end()
          ? PeakTensions{.thread = m.thread_tension, .tether = m.tether_tension}
          : PeakTensions{.thread = std::max(observed->second.thread, m.thread_tension),
                         .tether = std::max(observed->second.tether, m.tether_tension)};
  const double thread_safety = CalcSafetyFactor(m.thread_breaking_force, peak.thread);
  const double tether_safety = CalcSafetyFactor(m.tether_breaking_force, peak.tether);
  Json tether = nullptr;
  if (m.has_tether)
    tether = {{"tension", Number(m.tether_tension)},
              {"peak_tension", Number(peak.tether)},
              {"breaking_force", Number(m.tether_breaking_force)},
              {"safety_factor", Number(tether_safety)}};
  return {{"capture",
           {{"first_contact_time",
             first == summary.first_contact_times.end() ? Json(nullptr) : Number(first->second)},
            {"enclosed_fraction", Number(m.enclosed_fraction)},
            {"mouth_area_ratio", Number(m.mouth_area_ratio)},
            {"knot_coverage", Number(m.knot_coverage)},
            {"thread_coverage", Number(m.thread_coverage)},
            {"thread_tension", Number(m.thread_tension)},
            {"peak_thread_tension", Number(peak.thread)},
            {"thread_breaking_force", Number(m.thread_breaking_force)},
            {"thread_safety_factor", Number(thread_safety)},
            {"tether", tether},
            {"safety_factor", Number(std::min(thread_safety, tether_safety))},
            {"escaped", m.escaped}}}};
}

Json ProbeJson(const Probe& probe, const Model& model, const State& state,
               const RunSummary& summary, const std::vector<ContactPoint>& contacts) {
  if (probe.quantity == ProbeQuantity::kCapture)
    return CaptureJson(probe, model, state, contacts, summary);
  std::vector<double> values;
  EvaluateProbe(probe, model, state, summary.energy, contacts, &values);
  switch (probe.quantity) {
    case ProbeQuantity::kPosition:
    case ProbeQuantity::kVelocity: {
      Json vector = Json::array();
      for (double value : values) vector.push_back(Number(value));
      return {{probe.quantity == ProbeQuantity::kPosition ? "position" : "velocity", vector}};
    }
    case ProbeQuantity::kEnergy: {
      // Keyed by the column suffixes: NAME.kinetic → "kinetic", …
      const std::vector<std::string> columns = ProbeColumns(probe);
      Json energies = Json::object();
      for (std::size_t i = 0; i < values.size(); ++i)
        energies[columns[i].substr(probe.name.size() + 1)] = Number(values[i]);
      return {{"energy", energies}};
    }
    case ProbeQuantity::kCentroid:
    case ProbeQuantity::kCentroidVelocity: {
      Json vector = Json::array();
      for (double value : values) vector.push_back(Number(value));
      return {
          {probe.quantity == ProbeQuantity::kCentroid ? "centroid" : "centroid_velocity", vector}};
    }
    case ProbeQuantity::kMouthArea:
      return {{"mouth_area", Number(values[0])}};
    case ProbeQuantity::kDistance:
      return {{"distance", Number(values[0])}};
    case ProbeQuantity::kMaxTension:
      return {
          {"max_tension",
           {{"tension", Number(values[0])},
            {"thread", ThreadName(model.nets()[probe.net].name, static_cast<Index>(values[1]))}}}};
    case ProbeQuantity::kLinkForce:
      return {{"link_force",
               {{"tension", Number(values[0])},
                {"force", {Number(values[1]), Number(values[2]), Number(values[3])}}}}};
    case ProbeQuantity::kBodyPose:
      return {{"body_pose",
               {{"position", {Number(values[0]), Number(values[1]), Number(values[2])}},
                {"quaternion",
                 {Number(values[3]), Number(values[4]), Number(values[5]), Number(values[6])}}}}};
    case ProbeQuantity::kBodyVelocity:
      return {{"body_velocity",
               {{"linear", {Number(values[0]), Number(values[1]), Number(values[2])}},
                {"angular_body", {Number(values[3]), Number(values[4]), Number(values[5])}}}}};
    case ProbeQuantity::kContact:
      return {{"contact",
               {{"active", static_cast<int>(values[0])},
                {"normal_force", Number(values[1])},
                {"friction_force", Number(values[2])},
                {"force", {Number(values[3]), Number(values[4]), Number(values[5])}},
                {"moment", {Number(values[6]), Number(values[7]), Number(values[8])}},
                {"max_penetration", Number(values[9])}}}};
    case ProbeQuantity::kClearanceJoint:
      return {{"clearance_joint",
               {{"eccentricity", {Number(values[0]), Number(values[1]), Number(values[2])}},
                {"penetration", Number(values[3])},
                {"normal_force", Number(values[4])},
                {"friction_force", Number(values[5])},
                {"friction_moment", Number(values[6])},
                {"mode", static_cast<int>(values[7])}}}};
    case ProbeQuantity::kJointReaction:
      return {{"joint_reaction",
               {{"force", {Number(values[0]), Number(values[1]), Number(values[2])}},
                {"moment", {Number(values[3]), Number(values[4]), Number(values[5])}}}}};
    case ProbeQuantity::kCapture:
      break;  // CaptureJson
  }
  return Json::object();
}

}  // namespace

void WriteSummaryJson(const std::filesystem::path& path, const RunSummary& summary,
                      const std::vector<Probe>& probes, const Model& model, const State& state,
                      const std::vector<ContactPoint>& contacts) {
  Json probe_values = Json::object();
  for (const Probe& probe : probes)
    probe_values[probe.name] = ProbeJson(probe, model, state, summary, contacts);
  const Json json = {
      {"status", summary.completed     ? "completed"
                 : summary.interrupted ? "interrupted"
                                       : "failed"},
      {"message", summary.message},
      {"analysis", summary.analysis},
      {"time", Number(summary.end_time)},
      {"steps", summary.steps},
      {"newton_iterations", summary.newton_iterations},
      {"jacobian_updates", summary.jacobian_updates},
      {"step_cuts", summary.step_cuts},
      {"step_cut_reasons", summary.step_cut_reasons},
      {"pattern_rebuilds", summary.pattern_rebuilds},
      {"max_constraint_violation", Number(summary.max_constraint_violation)},
      {"wall_time_s", Number(summary.wall_time_s)},
      {"output_time_s", Number(summary.output_time_s)},
      {"energy", EnergyJson(summary.energy)},
      {"failures", FailuresJson(summary.failures)},
      {"probes", probe_values},
  };
  std::ofstream file(path);
  // Invalid UTF-8 in a message is replaced rather than failing the whole summary.
  file << json.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
  file.close();
  if (!file) throw InputError(fmt::format("cannot write {}", path.string()));
}

}  // namespace ancfnet
