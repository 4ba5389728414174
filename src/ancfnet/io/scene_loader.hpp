#pragma once
/// @file Loading a Scene from a YAML scene file. The format — every key, its unit, default and
/// allowed values — is described in docs/scene-format.md. The Model is built through
/// ModelBuilder, the same public API a C++ program uses.

#include <filesystem>
#include <string>

#include "ancfnet/io/scene.hpp"

namespace ancfnet {

/// Limits a loader applies beyond the plausibility of each value.
struct LoadOptions {
  /// A dynamic analysis whose estimated work, steps × unknowns (end_time / time_step times the
  /// model's coordinates), exceeds this is refused at `time_step` with the estimate and the hint
  /// `--force`; 0: no limit (the CLI's `run --force`, and every use but `run` and `check`).
  double max_unknown_steps = 0.0;
};

/// Estimated work above which `ancfnet run` asks for --force: 10¹² unknown-steps take about
/// three months on one core at the 1.5·10⁵ unknown-steps per second of the S3 net drop.
inline constexpr double kMaxUnknownSteps = 1e12;

/// Reads and parses the scene file `file`. Throws InputError "FILE: cannot open scene file" when
/// it cannot be read, refuses at once (before reading) a file that is not a regular file (a
/// device, a pipe) or holds more than 64 MiB, and throws as ParseScene otherwise.
Scene LoadScene(const std::filesystem::path& file, const LoadOptions& options = {});

/// Parses a scene from YAML text; `source_name` names it in messages and in Scene::source.
/// Relative paths in the scene (a mesh target's `file`) are taken from `scene_directory` (the
/// working directory when empty); LoadScene passes the scene file's directory.
/// Throws InputError with a one-line message "SOURCE:LINE:COLUMN: what is wrong (key 'KEY')" on
/// malformed YAML, an unknown or missing key, a value of the wrong type or out of range, an
/// unknown name, or a model the ModelBuilder refuses.
Scene ParseScene(const std::string& yaml_text, const std::string& source_name = "<string>",
                 const std::filesystem::path& scene_directory = {},
                 const LoadOptions& options = {});

/// A scene of a model built in code (ModelBuilder: a C++ program, the Python module) with what to
/// run and record read from YAML text: a map with the scene file's keys `analysis`, `output` and
/// `probes` (each optional, read as in a scene file: docs/scene-format.md), whose probes name the
/// model's cables and point masses. `source_name` names the text in messages and in
/// Scene::source. Throws InputError as ParseScene.
Scene ParseSceneSettings(Model model, const std::string& yaml_text,
                         const std::string& source_name = "<settings>");

}  // namespace ancfnet
