#include "ancfnet/run/run_scene.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ancfnet/analysis/first_contact.hpp"
#include "ancfnet/analysis/peak_tension.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/self_contact.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/checkpoint_file.hpp"
#include "ancfnet/io/contact_vtk_writer.hpp"
#include "ancfnet/io/output_directory.hpp"
#include "ancfnet/io/probe_csv_writer.hpp"
#include "ancfnet/io/vtk_writer.hpp"
#include "ancfnet/run/progress_reporter.hpp"
#include "ancfnet/solvers/static_solver.hpp"
#include "ancfnet/state/state_archive.hpp"

namespace ancfnet {
namespace {

// Probe rows and VTK frames for every output step.
class OutputWriters {
 public:
  // With `resume`, continues the outputs in `dir` from a checkpoint's part written by
  // SaveCheckpoint.
  OutputWriters(const Scene& scene, const std::filesystem::path& dir, ArchiveReader* resume)
      : scene_(scene),
        contact_(scene.model),
        self_contact_(scene.model),
        csv_(dir / "probes.csv", scene.probes,
             resume ? std::optional(resume->Read<std::uintmax_t>()) : std::nullopt),
        last_written_(MakeInitialState(scene.model)) {
    if (scene.output.write_vtk)
      vtk_ = std::make_unique<VtkSeriesWriter>(dir, "cables", scene.output.vtk_points_per_element);
    if (scene.output.write_vtk && scene.model.contact().enabled())
      contact_vtk_ = std::make_unique<ContactVtkWriter>(dir, "contacts");
    if (resume) LoadCheckpoint(resume);
  }
  // What a continued run needs to append to the outputs as this run would have: the size of
  // probes.csv, the frames of each series, the outputs written and the last of them.
  void SaveCheckpoint(ArchiveWriter* out) const {
    out->Write(csv_.size());
    out->Write(outputs_);
    out->Write(vtk_ ? vtk_->collection().frame_times() : std::vector<double>());
    out->Write(contact_vtk_ ? contact_vtk_->collection().frame_times() : std::vector<double>());
    last_energy_.Save(out);
    SaveState(last_written_, out);
  }
  // Writes nothing and throws SolverError when a value to be written is NaN or infinite, so
  // that the files only ever hold finite numbers. The VTK frame goes first: it checks the whole
  // centre line, from which the probe values are interpolated, before writing anything.
  void Write(const State& state, const EnergyAccount& energy) {
    CheckFinite(state, energy);
    const std::vector<ContactPoint>& contacts = CollectContacts(state);
    if (vtk_) vtk_->WriteFrame(scene_.model, state);
    if (contact_vtk_) contact_vtk_->WriteFrame(state.t, contacts);
    csv_.Append(scene_.model, state, energy, contacts);
    last_energy_ = energy;
    last_written_ = state;
    ++outputs_;
  }
  const EnergyAccount& last_energy() const { return last_energy_; }
  // The last state written (always finite) and the number of outputs.
  const State& last_written() const { return last_written_; }
  long outputs() const { return outputs_; }
  // The active contacts with the rigid targets and between threads and knots at `state`, in a
  // buffer reused between outputs.
  const std::vector<ContactPoint>& CollectContacts(const State& state) {
    contacts_.clear();
    contact_.SetBodyRotations(&state.body_rotation);
    contact_.CollectContacts(state.q, state.v, state.contact_history, &contacts_);
    if (!self_contact_.empty()) {
      self_contact_.FindCandidates(state, 0.0);
      self_contact_.CollectContacts(state.q, state.v, &contacts_);
    }
    return contacts_;
  }

 private:
  void LoadCheckpoint(ArchiveReader* in) {
    outputs_ = in->Read<long>();
    for (VtkCollection* series : {vtk_ ? &vtk_->collection() : nullptr,
                                  contact_vtk_ ? &contact_vtk_->collection() : nullptr}) {
      std::vector<double> times;
      in->Read(&times);
      if (series)
        series->Resume(times);
      else if (!times.empty())
        in->Fail("VTK frames of a scene that writes none");
    }
    last_energy_.Load(in);
    LoadState(in, &last_written_);
  }

  static void CheckFinite(const State& state, const EnergyAccount& energy) {
    if (!std::isfinite(state.t) || !state.q.allFinite() || !state.v.allFinite())
      throw SolverError("non-finite state (coordinates or velocities)", state.t);
    const std::pair<const char*, double> terms[] = {{"kinetic", energy.kinetic},
                                                    {"strain", energy.strain},
                                                    {"gravity", energy.gravity},
                                                    {"work", energy.work},
                                                    {"dissipated", energy.dissipated}};
    for (const auto& [name, value] : terms)
      if (!std::isfinite(value))
        throw SolverError(fmt::format("non-finite {} energy", name), state.t);
  }

  const Scene& scene_;
  TargetContact contact_;
  SelfContact self_contact_;
  std::vector<ContactPoint> contacts_;
  ProbeCsvWriter csv_;
  std::unique_ptr<VtkSeriesWriter> vtk_;
  std::unique_ptr<ContactVtkWriter> contact_vtk_;
  EnergyAccount last_energy_;
  State last_written_;
  long outputs_ = 0;
};

// Refuses checkpoint options a run cannot honour.
void CheckCheckpointOptions(const Scene& scene, const RunOptions& options, bool is_static) {
  const bool asked = options.checkpoint_every != 0.0 || !options.restart.empty();
  if (is_static && asked)
    throw InputError("--checkpoint-every and --restart are for dynamic analyses, not static ones");
  const double every = options.checkpoint_every;
  const double step = scene.analysis.dynamics.time_step;
  if (!std::isfinite(every) || every < 0.0 || (every > 0.0 && every < step))
    throw InputError(fmt::format(
        "--checkpoint-every {} s: must be 0 (none) or at least the time step {} s", every, step));
}

}  // namespace

RunSummary RunScene(const Scene& scene, const RunOptions& options) {
  const AnalysisType type = options.analysis_type.value_or(scene.analysis.type);
  const bool is_static = type == AnalysisType::kStatic;
  CheckCheckpointOptions(scene, options, is_static);
  std::vector<std::byte> checkpoint;
  std::optional<ArchiveReader> resume;
  if (!options.restart.empty()) {
    checkpoint = ReadCheckpointFile(options.restart, scene);
    resume.emplace(checkpoint.data(), checkpoint.size(), options.restart.string());
  }
  CreateOutputDirectory(options.output_dir);
  OutputWriters writers(scene, options.output_dir, resume ? &*resume : nullptr);
  // Observes the initial state and load steps through the outputs, and every accepted time step.
  FirstContactTracker first_contacts(scene.model, scene.probes);
  PeakTensionTracker peak_tensions(scene.model, scene.probes);
  if (resume) {
    first_contacts.Load(&*resume);
    peak_tensions.Load(&*resume);
  }
  const StepCallback step = [&](const State& s) {
    first_contacts.Observe(s);
    peak_tensions.Observe(s);
  };
  ProgressReporter progress(
      is_static ? "load factor" : "t =", is_static ? 1.0 : scene.analysis.dynamics.end_time,
      options.show_progress);

  State state = MakeInitialState(scene.model);
  std::chrono::steady_clock::duration output_time{};
  const OutputCallback output = [&](const State& s, const EnergyAccount& energy) {
    step(s);
    const auto start = std::chrono::steady_clock::now();
    writers.Write(s, energy);
    output_time += std::chrono::steady_clock::now() - start;
    progress.Update(s.t, writers.outputs());
    if (options.on_output) options.on_output(s);
  };
  TimeLoopCheckpoints checkpoints{.every = options.checkpoint_every,
                                  .resume = resume ? &*resume : nullptr};
  if (options.checkpoint_every > 0.0)
    checkpoints.write = [&](const State&, const std::vector<std::byte>& loop) {
      ArchiveWriter out;
      writers.SaveCheckpoint(&out);
      first_contacts.Save(&out);
      peak_tensions.Save(&out);
      out.WriteBytes(loop.data(), loop.size());
      WriteCheckpointFile(options.output_dir / "checkpoint.bin", scene, out.bytes());
    };

  RunSummary summary;
  summary.analysis = is_static ? "static" : "dynamic";
  const SolveResult result =
      is_static ? SolveStatic(scene.model, scene.analysis.statics, output, &state)
                : SolveDynamic(scene.model, scene.analysis.dynamics, scene.output.interval, output,
                               &state, checkpoints, step);
  progress.Finish();
  const State& last_written = writers.last_written();
  summary.completed = result.completed;
  summary.interrupted = result.interrupted;
  summary.message = result.message;
  summary.end_time = last_written.t;
  summary.steps = result.statistics.steps;
  summary.newton_iterations = result.statistics.newton_iterations;
  summary.jacobian_updates = result.statistics.jacobian_updates;
  summary.step_cuts = result.statistics.step_cuts;
  summary.pattern_rebuilds = result.statistics.pattern_rebuilds;
  summary.max_constraint_violation = result.statistics.max_constraint_violation;
  summary.step_cut_reasons = result.statistics.step_cut_reasons;
  summary.outputs = writers.outputs();
  summary.wall_time_s = progress.elapsed_s();
  summary.output_time_s = std::chrono::duration<double>(output_time).count();
  summary.energy = writers.last_energy();
  summary.failures = result.failures;
  summary.first_contact_times = first_contacts.times();
  summary.peak_tensions = peak_tensions.peaks();
  // Final values are those of the last state written, which is always finite.
  WriteSummaryJson(options.output_dir / "summary.json", summary, scene.probes, scene.model,
                   last_written, writers.CollectContacts(last_written));
  return summary;
}

}  // namespace ancfnet
