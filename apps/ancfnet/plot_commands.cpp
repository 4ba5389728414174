#include "plot_commands.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "tool_script.hpp"

namespace ancfnet {

namespace {

PlotCommand AddPlotCommand(CLI::App& app, const std::string& name, const std::string& description,
                           const std::string& script, std::vector<std::string> needed_files) {
  PlotCommand command;
  command.command = app.add_subcommand(name, description);
  command.script = script;
  command.needed_files = std::move(needed_files);
  command.command->allow_extras();
  command.command->footer(
      fmt::format("Every option after RUN_DIR goes to {0}: see "
                  "`python3 tools/{0} --help` (docs/plots.md).",
                  script));
  return command;
}

}  // namespace

std::vector<PlotCommand> AddPlotCommands(CLI::App& app) {
  std::vector<PlotCommand> commands = {
      AddPlotCommand(app, "animate",
                     "Movie of a run's net and bodies (RUN_DIR/animation.mp4, or .gif without "
                     "ffmpeg); options -o FILE, --fps N, --every K, --view front|side|top|oblique, "
                     "--scene SCENE (draw its contact targets)",
                     "animate_run.py", {"cables.pvd"}),
      AddPlotCommand(app, "report",
                     "One-page capture report of a run (RUN_DIR/report.png): snapshots from "
                     "three views, energy, contact forces, tension, target rates; options "
                     "--times T..., --scene SCENE, -o FILE, --pdf",
                     "capture_report.py", {"probes.csv", "cables.pvd"}),
  };
  // The options live in a vector that no longer moves: bind them now.
  for (PlotCommand& command : commands)
    command.command->add_option("run_dir", command.run_dir, "Output folder of `ancfnet run`")
        ->required();
  return commands;
}

void RunPlotCommand(const PlotCommand& command) {
  const std::filesystem::path run_dir = command.run_dir;
  if (!std::filesystem::is_directory(run_dir))
    throw InputError(fmt::format("{}: no such folder (give the output folder of `ancfnet run`)",
                                 command.run_dir));
  for (const std::string& name : command.needed_files)
    if (!std::filesystem::is_regular_file(run_dir / name) ||
        std::filesystem::file_size(run_dir / name) == 0)
      throw InputError(fmt::format("{}: no run data ({} missing or empty)", command.run_dir,
                                   (run_dir / name).string()));
  std::vector<std::string> arguments = {command.run_dir};
  for (const std::string& extra : command.command->remaining()) arguments.push_back(extra);
  ExecToolScript(FindToolScript(command.script), arguments);
}

}  // namespace ancfnet
