#include "study_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <thread>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"
#include "ancfnet/study/mpi_case_dispatch.hpp"
#include "ancfnet/study/run_study.hpp"
#include "ancfnet/study/study.hpp"
#include "tool_script.hpp"

namespace ancfnet {
namespace {

extern "C" void StopStudyOnSignal(int signal) { RequestInterrupt(signal); }

// SIGINT and SIGTERM stop the study after the running cases (passed on to them); without
// SA_RESTART, so that they end its wait for a case; a second one ends the process at once.
void StopStudyOnSignals() {
  struct sigaction action = {};
  action.sa_handler = StopStudyOnSignal;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

void AddStudyCommand(CLI::App& app, StudyArguments* arguments) {
  arguments->command = app.add_subcommand(
      "study",
      "Run a scene many times with values varied on a grid or sampled (docs/studies.md); "
      "under mpirun, across the ranks");
  arguments->command->add_option("study", arguments->study_file, "Study file (YAML)")->required();
  arguments->command->add_option("-o,--output", arguments->output_dir,
                                 "Output directory (default: out/<study name>)");
  arguments->command
      ->add_option("-j,--jobs", arguments->workers, "Cases run at a time (default: one per core)")
      ->check(CLI::Range(1, 4096));
  arguments->command->footer(fmt::format("MPI support: {}", BuiltWithMpi() ? "yes" : "no"));
}

int RunStudyCommand(const StudyArguments& arguments) {
  const Study study = LoadStudy(arguments.study_file);
  StudyOptions options;
  options.output_dir =
      arguments.output_dir.empty()
          ? std::filesystem::path("out") / std::filesystem::path(arguments.study_file).stem()
          : std::filesystem::path(arguments.output_dir);
  options.executable = std::filesystem::read_symlink("/proc/self/exe");
  options.workers = arguments.workers > 0
                        ? arguments.workers
                        : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  StopStudyOnSignals();
  const StudyOutcome outcome = RunStudy(study, options);
  if (outcome.interrupted) {
    fmt::print(stderr, "study: interrupted; run the same command again to continue\n");
    return 128 + InterruptRequested();
  }
  if (!outcome.wrote_table) return 0;
  const std::filesystem::path table = options.output_dir / "study.csv";
  fmt::print(stderr, "study: {} cases, {} failed; table in {}\n", outcome.cases, outcome.failed,
             table.string());
  if (!study.plot) return 0;
  ExecToolScript(FindToolScript("plot_study.py"),
                 {table.string(), "--x", study.plot->x, "--y", study.plot->y, "--metric",
                  study.plot->metric, "-o", (options.output_dir / "study.png").string()});
}

}  // namespace ancfnet
