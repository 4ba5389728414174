#pragma once
/// @file `ancfnet study STUDY.yaml -o DIR [-j N]`: a base scene run with values varied on a grid
/// or sampled, each case by `ancfnet run`, on worker processes or across the ranks of
/// `mpirun`; the table DIR/study.csv and, when the study asks, the plot DIR/study.png
/// (docs/studies.md).

#include <CLI/CLI.hpp>
#include <string>

namespace ancfnet {

struct StudyArguments {
  CLI::App* command = nullptr;
  std::string study_file;
  std::string output_dir;
  int workers = 0;  ///< 0: one per core
};

/// Adds the subcommand `study` to `app`.
void AddStudyCommand(CLI::App& app, StudyArguments* arguments);

/// Runs the study; returns the exit code: 0 when every case ran (failed cases included), 128 +
/// the signal when interrupted. With a `plot`, the process becomes tools/plot_study.py (its exit
/// code is the tool's). Throws InputError for a bad study file or output folder.
int RunStudyCommand(const StudyArguments& arguments);

}  // namespace ancfnet
