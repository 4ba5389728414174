#pragma once
/// @file A scene: the model plus what to run and what to record. Loaded from YAML by
/// io/scene_loader.hpp or assembled in C++.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"

namespace ancfnet {

struct OutputSettings {
  /// Interval between output rows and frames (s of simulated time); 0 writes every step. Static
  /// analyses write one row per load step.
  double interval = 0.0;
  bool write_vtk = true;          ///< VTK frames and the .pvd collection
  int vtk_points_per_element = 4; ///< points drawn per element along the deformed centre line
};

struct Scene {
  Model model;
  std::vector<Probe> probes;
  AnalysisSettings analysis;
  OutputSettings output;
  std::string source;  ///< file the scene came from (for messages)
  /// FNV-1a hash of the scene's text (common/fnv_hash.hpp), 0 for a scene built in C++: a
  /// checkpoint is refused by a scene with another hash.
  std::uint64_t text_hash = 0;
};

}  // namespace ancfnet
