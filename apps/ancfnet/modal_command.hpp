#pragma once
// `ancfnet modal SCENE --modes K [-o DIR] [--about reference|equilibrium] [--shift S]`.

#include <CLI/CLI.hpp>
#include <string>

namespace ancfnet {

struct ModalCommand {
  CLI::App* command = nullptr;
  std::string scene_file;
  std::string output_dir;
  int modes = 6;
  std::string about = "reference";
  double shift = 0.0;
};

/// Adds the subcommand and its options to `app`; `options` receives them.
void AddModalCommand(CLI::App& app, ModalCommand* options);

/// Runs it: prints the table of modes and writes modes.json and the VTK frames. Returns the exit
/// code (0); InputError and SolverError propagate to main.
int RunModalCommand(const ModalCommand& options);

}  // namespace ancfnet
