#pragma once
/// @file What `ancfnet check` prints about a valid scene.

#include <cstdio>

#include "ancfnet/io/scene.hpp"

namespace ancfnet {

/// Prints the cables, the unknowns, the loads, the probes and the analysis of a scene.
void PrintSceneReport(const Scene& scene, std::FILE* out);

}  // namespace ancfnet
