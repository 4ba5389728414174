#pragma once
/// @file Runs a scene: the analysis it asks for, with its outputs written into a directory.

#include <filesystem>
#include <functional>
#include <optional>

#include "ancfnet/io/scene.hpp"
#include "ancfnet/io/summary_writer.hpp"

namespace ancfnet {

struct RunOptions {
  std::filesystem::path output_dir;
  /// Overrides scene.analysis.type (the CLI's `static` subcommand).
  std::optional<AnalysisType> analysis_type;
  bool show_progress = true;
  /// Simulated time between checkpoints (s), written to output_dir/checkpoint.bin (the latest
  /// only; also when an interrupt stops the run). 0: none. Dynamic analyses only; at least the
  /// scene's time step.
  double checkpoint_every = 0.0;
  /// A checkpoint of this scene to continue from, appending to the outputs in output_dir that
  /// the run which wrote it left there. Empty: start at t = 0.
  std::filesystem::path restart;
  /// Called with the state just written at each output step (t = 0 and every output time), after
  /// its probe row and frames; it may throw to abandon the run, which then writes no summary.
  /// Empty: none. The Python module steps a run through it.
  std::function<void(const State&)> on_output;
};

/// Runs the analysis and writes into options.output_dir: probes.csv (one row per output step),
/// cables_NNNNNN.vtp frames with cables.pvd, with contact targets contacts_NNNNNN.vtp frames (the
/// active contact points) with contacts.pvd, and summary.json. A solver failure does not throw:
/// the outputs written so far are kept, summary.json says "failed" with the time and the reason,
/// and the returned summary has completed == false. An interrupt (common/interrupt.hpp) stops the
/// run after the step in progress: the state reached is written, summary.json says
/// "interrupted", and the summary has completed == false and interrupted == true. A run
/// continued from a checkpoint ends with outputs byte for byte those of the run that was never
/// stopped (docs/reliability.md, "Checkpoints"). Throws InputError when the directory cannot be
/// written, when a checkpoint cannot be written, or when the one to continue from is refused
/// (another scene, damaged, truncated) or the outputs it continues are missing.
RunSummary RunScene(const Scene& scene, const RunOptions& options);

}  // namespace ancfnet
