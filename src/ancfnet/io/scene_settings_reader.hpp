#pragma once
/// @file Readers of the `analysis` and `output` maps of a scene file (docs/scene-format.md).

#include "ancfnet/io/scene.hpp"
#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"

namespace ancfnet {

/// The `analysis` map: `type` (static | dynamic, required) and any static, dynamic and Newton keys,
/// whatever the type (a CLI subcommand may switch it). Keys left out keep the defaults of
/// analysis_settings.hpp; Newton keys set both the static and the dynamic NewtonSettings.
/// Throws InputError (with the file position) on an unknown key or an out-of-range value.
AnalysisSettings ReadAnalysisSettings(const YamlValue& analysis);

/// Refuses (at `time_step` of the `analysis` map, else at the map) a dynamic analysis whose
/// estimated work, (end_time / time_step) steps × `unknowns`, exceeds `max_unknown_steps`, with
/// the estimate and the hint --force.
void CheckRunWork(const DynamicSettings& dynamics, Index unknowns, double max_unknown_steps,
                  const YamlValue& analysis);

/// The `output` map: interval (s, ≥ 0), vtk (bool), vtk_points_per_element (1 … 64).
OutputSettings ReadOutputSettings(const YamlValue& output);

}  // namespace ancfnet
