#pragma once
/// @file The named materials and sections of a scene file, looked up by the readers of cables
/// and nets.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ancfnet/io/closest_name.hpp"
#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/material.hpp"

namespace ancfnet {

// Named definitions in file order (the order they are listed in messages).
template <typename T>
using NamedList = std::vector<std::pair<std::string, T>>;

struct Library {
  NamedList<Material> materials;
  NamedList<Section> sections;
  // The maps they were read from, read again for a beam (io/beam_reader.hpp), which needs ν and
  // the section's shape.
  NamedList<YamlValue> material_values;
  NamedList<YamlValue> section_values;
};

// The definition named by `value`; the error lists the known names or suggests the closest.
template <typename T>
const T& Lookup(const NamedList<T>& list, const YamlValue& value, std::string_view what,
                std::string_view list_label) {
  const std::string name = value.AsString();
  std::vector<std::string_view> names;
  for (const auto& [known, definition] : list) {
    if (known == name) return definition;
    names.push_back(known);
  }
  value.Fail(fmt::format("no {} named '{}'{}", what, name, SuggestName(name, names, list_label)));
}

// bending: exact (the curvature, default for cables) | simple (½ EI ∫ |r''|², default for nets).
inline BendingModel ReadBendingModel(const YamlValue& value) {
  return value.AsEnum<BendingModel>(
      {{"exact", BendingModel::kExactCurvature}, {"simple", BendingModel::kSecondDerivative}});
}

}  // namespace ancfnet
