#pragma once
/// @file `ancfnet animate RUN_DIR` and `ancfnet report RUN_DIR`: a movie and a one-page report
/// of a run's outputs, drawn by the Python scripts tools/animate_run.py and
/// tools/capture_report.py (docs/plots.md).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace ancfnet {

/// The command line of one plotting subcommand.
struct PlotCommand {
  CLI::App* command = nullptr;
  std::string script;                     ///< file name in tools/
  std::vector<std::string> needed_files;  ///< in RUN_DIR, checked before Python starts
  std::string run_dir;
};

/// Adds `animate` and `report` to `app`; their options other than RUN_DIR go to the script
/// (`python3 tools/animate_run.py --help` lists them).
std::vector<PlotCommand> AddPlotCommands(CLI::App& app);

/// Runs the script of `command` on its run folder: replaces the process, so it returns only
/// by throwing InputError (exit code 2) for a missing folder or file, script or interpreter.
[[noreturn]] void RunPlotCommand(const PlotCommand& command);

}  // namespace ancfnet
