#pragma once
/// @file Modal analysis of a scene (`ancfnet modal`): the lowest modes about the reference
/// configuration or a static equilibrium, written as modes.json and VTK frames of the shapes.

#include <filesystem>

#include "ancfnet/io/scene.hpp"
#include "ancfnet/solvers/modal.hpp"

namespace ancfnet {

enum class Linearisation {
  kReference,    ///< about the initial (reference) configuration
  kEquilibrium,  ///< about the static equilibrium of the scene's loads (e.g. a taut net)
};

struct ModalOptions {
  std::filesystem::path output_dir;
  ModalSettings settings;
  Linearisation about = Linearisation::kReference;
};

/// Runs the modal analysis and writes into options.output_dir: modes.json
/// `{"about", "unknowns", "modes": [{"mode", "frequency_hz", "omega_rad_s", "period_s",
/// "damping_ratio", "rigid"}]}` (damping_ratio null for rigid modes) and modes_NNNNNN.vtp with
/// modes.pvd, frame k showing mode k + 1 with its largest displacement at a tenth of the
/// model's size (its "time" is the mode number). Throws InputError for bad options or an
/// unwritable directory, SolverError when the static solve or the eigensolver fails.
ModalResult RunModal(const Scene& scene, const ModalOptions& options);

}  // namespace ancfnet
