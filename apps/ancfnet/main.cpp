// The ancfnet command-line tool: run, static, check and modal for a scene file; identify
// modes in a probes.csv file; animate and report a run's outputs; study a scene with values
// varied.
// Exit codes: 0 success, 2 invalid input (one line on stderr; also a model too large for the
// memory), 3 the solver gave up (outputs written so far are kept and summary.json says why),
// 130 / 143 a run stopped by SIGINT / SIGTERM after the step in progress (outputs consistent,
// summary.json says "interrupted"), 1 an unexpected internal error (a bug).

#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/io/yaml_document.hpp"
#include "ancfnet/run/run_scene.hpp"
#include "assumed_modes_command.hpp"
#include "identify_command.hpp"
#include "modal_command.hpp"
#include "plot_commands.hpp"
#include "scene_report.hpp"
#include "study_command.hpp"

namespace {

constexpr int kExitInternalError = 1;
constexpr int kExitInputError = 2;
constexpr int kExitSolverFailure = 3;

// The first SIGINT or SIGTERM asks the run to stop after the step in progress; a second one
// ends the process at once (the handler is reset to the default action).
extern "C" void RequestStopOnSignal(int signal) {
  ancfnet::RequestInterrupt(signal);
  std::signal(signal, SIG_DFL);
}

// The work limit of `run` and `check`, lifted by --force.
ancfnet::LoadOptions WorkLimit(bool force) {
  return {.max_unknown_steps = force ? 0.0 : ancfnet::kMaxUnknownSteps};
}

// `scene_directory`: where the scene's relative paths are taken from; empty: the scene file's
// folder.
int RunCommand(const std::string& scene_file, const std::string& scene_directory,
               const std::string& output_dir, bool quiet, std::optional<ancfnet::AnalysisType> type,
               bool force, ancfnet::RunOptions options) {
  std::signal(SIGINT, RequestStopOnSignal);
  std::signal(SIGTERM, RequestStopOnSignal);
  // A static solve takes no time steps: no work limit.
  const ancfnet::LoadOptions load = WorkLimit(force || type.has_value());
  const ancfnet::Scene scene =
      scene_directory.empty() ? ancfnet::LoadScene(scene_file, load)
                              : ancfnet::ParseScene(ancfnet::ReadInputFile(scene_file, "scene"),
                                                    scene_file, scene_directory, load);
  options.output_dir = output_dir.empty()
                           ? std::filesystem::path("out") / std::filesystem::path(scene_file).stem()
                           : std::filesystem::path(output_dir);
  options.analysis_type = type;
  options.show_progress = !quiet;
  const ancfnet::RunSummary summary = ancfnet::RunScene(scene, options);
  if (summary.interrupted) {
    fmt::print(stderr, "\nancfnet: {}; outputs up to t = {:.9g} kept in {}\n", summary.message,
               summary.end_time, options.output_dir.string());
    if (options.checkpoint_every > 0.0)
      fmt::print(stderr, "ancfnet: continue with: ancfnet run {} -o {} --restart {}\n", scene_file,
                 options.output_dir.string(), (options.output_dir / "checkpoint.bin").string());
    return 128 + ancfnet::InterruptRequested();
  }
  if (!summary.completed) {
    fmt::print(stderr, "ancfnet: {}\n", summary.message);
    if (summary.outputs > 0)
      fmt::print(stderr, "ancfnet: outputs up to t = {:.9g} kept in {}\n", summary.end_time,
                 options.output_dir.string());
    else
      fmt::print(stderr, "ancfnet: no output step was written; summary in {}\n",
                 options.output_dir.string());
    return kExitSolverFailure;
  }
  if (!quiet)
    fmt::print(
        "{} analysis completed: {} steps, {} Newton iterations, {} Jacobian updates, "
        "{} step cuts, {} pattern rebuilds, {:.3f} s; results in {}\n",
        summary.analysis, summary.steps, summary.newton_iterations, summary.jacobian_updates,
        summary.step_cuts, summary.pattern_rebuilds, summary.wall_time_s,
        options.output_dir.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // One thread unless OMP_NUM_THREADS asks for more: the element loops are short, and a second
  // thread spin-waiting at their barriers costs far more than it saves once another process
  // wants the core (docs/benchmarks.md, "Threads and the shared machine").
  if (!std::getenv("OMP_NUM_THREADS")) omp_set_num_threads(1);
  CLI::App app{"ancfnet: dynamics of cables, ropes and tether nets with ANCF elements"};
  app.require_subcommand(1);
  std::string scene_file;
  std::string output_dir;
  bool quiet = false;

  CLI::App* run = app.add_subcommand("run", "Run the analysis the scene file asks for");
  CLI::App* run_static = app.add_subcommand("static", "Solve the static equilibrium of a scene");
  for (CLI::App* command : {run, run_static}) {
    command->add_option("scene", scene_file, "Scene file (YAML)")->required();
    command->add_option("-o,--output", output_dir, "Output directory (default: out/<scene name>)");
    command->add_flag("-q,--quiet", quiet, "No progress line and no closing message");
  }
  bool force = false;
  run->add_flag("--force", force,
                "Run even when the estimated work (steps × unknowns) is beyond what finishes in "
                "months");
  ancfnet::RunOptions run_options;
  run->add_option("--checkpoint-every", run_options.checkpoint_every,
                  "Write the complete state to OUTPUT/checkpoint.bin every T s of simulated time "
                  "(and when interrupted)")
      ->type_name("T");
  run->add_option("--restart", run_options.restart,
                  "Continue from a checkpoint of this scene, appending to the outputs in OUTPUT")
      ->type_name("CHECKPOINT");
  // Hidden: the case scenes of a study take their relative paths from the base scene's folder.
  std::string scene_directory;
  run->add_option("--scene-dir", scene_directory,
                  "Take the scene's relative paths from this folder, not the scene file's")
      ->group("");
  CLI::App* check = app.add_subcommand("check", "Validate a scene file and describe the model");
  check->add_option("scene", scene_file, "Scene file (YAML)")->required();
  ancfnet::ModalCommand modal;
  ancfnet::AddModalCommand(app, &modal);
  ancfnet::IdentifyArguments identify_arguments;
  CLI::App* identify = ancfnet::AddIdentifyCommand(app, &identify_arguments);
  ancfnet::AssumedModesArguments assumed_modes;
  ancfnet::AddAssumedModesCommand(app, &assumed_modes);
  const std::vector<ancfnet::PlotCommand> plot_commands = ancfnet::AddPlotCommands(app);
  ancfnet::StudyArguments study;
  ancfnet::AddStudyCommand(app, &study);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitInputError;
  }
  try {
    if (*check) {
      ancfnet::PrintSceneReport(ancfnet::LoadScene(scene_file, WorkLimit(false)), stdout);
      return 0;
    }
    if (*modal.command) return ancfnet::RunModalCommand(modal);
    if (*identify) return ancfnet::RunIdentifyCommand(identify_arguments, stdout);
    if (*assumed_modes.command) return ancfnet::RunAssumedModesCommand(assumed_modes);
    if (*study.command) return ancfnet::RunStudyCommand(study);
    for (const ancfnet::PlotCommand& plot : plot_commands)
      if (*plot.command) ancfnet::RunPlotCommand(plot);
    const auto type = *run_static ? std::optional(ancfnet::AnalysisType::kStatic) : std::nullopt;
    return RunCommand(scene_file, scene_directory, output_dir, quiet, type, force, run_options);
  } catch (const ancfnet::InputError& e) {
    fmt::print(stderr, "ancfnet: {}\n", e.what());
    return kExitInputError;
  } catch (const ancfnet::SolverError& e) {  // RunScene reports these itself; never abort
    fmt::print(stderr, "ancfnet: stopped at t = {:.9g}: {}\n", e.time(), e.what());
    return kExitSolverFailure;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "ancfnet: out of memory: the model is too large for this machine\n");
    return kExitInputError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ancfnet: internal error: {}\n", e.what());
    return kExitInternalError;
  }
}
