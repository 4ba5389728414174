#pragma once
/// @file A plausibility check of a cable's or a net's cross-section against its element length.

#include <string_view>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/material.hpp"

namespace ancfnet {

/// Refuses (at `where`, the `section` key) a cross-section thicker than the elements of `owner`
/// (a cable, a net's threads) are long: its diameter d = 2 √(A/π), that of the circle of its area,
/// above the element length ℓ (m). An ANCF cable element models a slender thread; d > ℓ is a
/// wrong unit or a typo (a 1000 km thread diameter on a 1 m cable was once accepted). A zero
/// length passes: the model builder refuses it with its own reason.
void CheckSlenderElements(const Section& section, double element_length, std::string_view owner,
                          const YamlValue& where);

}  // namespace ancfnet
