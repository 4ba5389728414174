#pragma once
/// @file The JSON summary of a run: how it ended, what it cost, and the final probe values.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/analysis/failure.hpp"
#include "ancfnet/analysis/peak_tension.hpp"
#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Counters and outcome of a static or dynamic run.
struct RunSummary {
  std::string analysis;   ///< "static" or "dynamic"
  bool completed = true;     ///< false when the solver gave up or the run was interrupted
  bool interrupted = false;  ///< stopped on request (a signal) after writing the state reached
  std::string message;       ///< why the run stopped early (empty when it completed)
  double end_time = 0.0;  ///< final time (s) or load factor reached
  long steps = 0;         ///< accepted steps
  long newton_iterations = 0;
  long jacobian_updates = 0;
  long step_cuts = 0;
  long pattern_rebuilds = 0;           ///< new patterns of the iteration matrix (contact)
  std::map<std::string, long> step_cut_reasons;  ///< rejected attempts by reason
  /// Largest violation max_i |g_i| of the ideal joints over the run (m, or 1 for direction
  /// equations); 0 without joints.
  double max_constraint_violation = 0.0;
  long outputs = 0;                    ///< output steps written (rows of probes.csv)
  double wall_time_s = 0.0;            ///< whole analysis, outputs included (s)
  double output_time_s = 0.0;          ///< part of it spent writing probes.csv and VTK frames (s)
  EnergyAccount energy;                ///< energies at the end (J)
  std::vector<FailureEvent> failures;  ///< threads and connections that broke
  /// Capture probe name → the first time (s), of the initial state or an accepted step, at which
  /// its net touched its target (FirstContactTracker); absent: never.
  std::map<std::string, double> first_contact_times;
  /// Capture probe name → the largest thread and tether tensions of its net over the run, at the
  /// initial state and every accepted step (PeakTensionTracker); absent: the last output's.
  std::map<std::string, PeakTensions> peak_tensions;
};

/// Writes `summary` and the final values of `probes` (EvaluateProbe on `state` with
/// summary.energy and `contacts`, the active contacts at `state`) to `path` as JSON, indented by 2:
/// `{"status": "completed"|"failed"|"interrupted", "message", "analysis", "time", "steps",
/// "newton_iterations", "jacobian_updates", "step_cuts", "step_cut_reasons": {REASON: count},
/// "pattern_rebuilds", "max_constraint_violation", "wall_time_s", "output_time_s", "energy":
/// {"kinetic", "strain", "gravity", "work", "dissipated", "balance"}, "failures": [{"time", "what",
/// "tension"}], "probes": {NAME: {"position": [x, y, z]} |
/// {"velocity": [vx, vy, vz]} | {"energy": {"kinetic", …}} | {"contact": {"active",
/// "normal_force", "friction_force", "force": [fx, fy, fz], "moment": [mx, my, mz],
/// "max_penetration"}} | {"capture": {"first_contact_time", "enclosed_fraction",
/// "mouth_area_ratio", "knot_coverage", "thread_coverage", "thread_tension",
/// "peak_thread_tension", "thread_breaking_force", "thread_safety_factor", "tether": {"tension",
/// "peak_tension", "breaking_force", "safety_factor"} (null without a tether), "safety_factor"
/// (the smaller of the two), "escaped"}}: tensions at `state` and their peaks over the run
/// (summary.peak_tensions), the safety factors against the peaks
/// | …}}`. Units as in the CSV (s, m, m/s, J, N). Non-finite numbers (an infinite breaking force or
/// safety factor, a first contact time that never came) are written as null. Throws InputError
/// "cannot write PATH" on failure.
void WriteSummaryJson(const std::filesystem::path& path, const RunSummary& summary,
                      const std::vector<Probe>& probes, const Model& model, const State& state,
                      const std::vector<ContactPoint>& contacts);

}  // namespace ancfnet
