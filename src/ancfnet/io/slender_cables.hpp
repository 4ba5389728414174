#pragma once
/// @file A plausibility check of a cable's or a net's cross-section against its length.

#include <string_view>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/material.hpp"

namespace ancfnet {

/// Refuses (at `where`, the `section` key) a cross-section thicker than `owner` (a cable, the
/// shortest thread of a net between its knots) is long: its diameter d = 2 √(A/π), that of the
/// circle of its area, above the length ℓ (m). A cable model is a slender thread; d > ℓ is a wrong
/// unit or a typo (a 1000 km thread diameter on a 1 m cable was once accepted). Elements shorter
/// than d are fine (a refined mesh of a thick rope). A zero length passes: the model builder
/// refuses it with its own reason.
void CheckSlenderCable(const Section& section, double length, std::string_view owner,
                       const YamlValue& where);

}  // namespace ancfnet
