#include "modal_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/run/run_modal.hpp"

namespace ancfnet {

void AddModalCommand(CLI::App& app, ModalCommand* options) {
  options->command = app.add_subcommand(
      "modal", "Natural frequencies, damping ratios and mode shapes of the linearised scene");
  CLI::App* c = options->command;
  c->add_option("scene", options->scene_file, "Scene file (YAML)")->required();
  c->add_option("-o,--output", options->output_dir,
                "Output directory (default: out/<scene>_modes)");
  c->add_option("--modes", options->modes, "Number of modes (the lowest)")
      ->check(CLI::PositiveNumber);
  c->add_option("--about", options->about,
                "Linearise about the reference configuration or the static equilibrium")
      ->check(CLI::IsMember({"reference", "equilibrium"}));
  c->add_option("--shift", options->shift,
                "Shift σ (rad²/s²) of the eigensolver; the modes nearest it (default: automatic)");
}

int RunModalCommand(const ModalCommand& options) {
  const Scene scene = LoadScene(options.scene_file);
  ModalOptions run;
  run.output_dir = options.output_dir.empty()
                       ? std::filesystem::path("out") /
                             (std::filesystem::path(options.scene_file).stem().string() + "_modes")
                       : std::filesystem::path(options.output_dir);
  run.settings.num_modes = options.modes;
  run.settings.shift = options.shift;
  run.about =
      options.about == "equilibrium" ? Linearisation::kEquilibrium : Linearisation::kReference;
  const ModalResult modes = RunModal(scene, run);
  fmt::print("{:>5} {:>14} {:>14} {:>10}\n", "mode", "f [Hz]", "ω [rad/s]", "ζ [%]");
  for (Eigen::Index i = 0; i < modes.omega.size(); ++i) {
    const double zeta = modes.damping_ratio[i];
    fmt::print("{:>5} {:>14.6g} {:>14.6g} {:>10}{}\n", i + 1, modes.frequency_hz[i], modes.omega[i],
               std::isfinite(zeta) ? fmt::format("{:.4f}", 100.0 * zeta) : "—",
               modes.rigid[i] ? "  (rigid)" : "");
  }
  fmt::print("modes.json and modes.pvd in {}\n", run.output_dir.string());
  return 0;
}

}  // namespace ancfnet
