#pragma once
/// @file Reads a net (model/net_builder.hpp) from the `nets:` list of a scene file; the keys are
/// documented in docs/scene-format.md, "nets".

#include <string>
#include <vector>

#include "ancfnet/io/scene_library.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// Adds the net described by `item` to `builder` and appends its knot names (point masses) to
/// `point_masses`. InputError with file, line and key on any mistake.
void ReadNet(const YamlValue& item, const Library& library, ModelBuilder* builder,
             std::vector<std::string>* point_masses);

}  // namespace ancfnet
