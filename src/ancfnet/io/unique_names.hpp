#pragma once
/// @file Names that must be unique within one kind of thing in a scene (probes, contact targets,
/// spring-dampers): each is read with YamlValue::AsName and checked in O(1), so a scene with many
/// items is still read in time linear in its size.

#include <string>
#include <unordered_map>

#include "ancfnet/io/yaml_reader.hpp"

namespace ancfnet {

class UniqueNames {
 public:
  /// `kind` names the things in the plural, as in "two probes are named 'x'".
  explicit UniqueNames(std::string kind) : kind_(std::move(kind)) {}
  /// The name `value` holds (AsName); throws InputError at `value` when an earlier item of this
  /// kind has it, naming the line of the first.
  std::string Read(const YamlValue& value) { return Claim(value, value.AsName()); }
  /// Registers `name` for the item at `where` (e.g. a default name of an unnamed item) and
  /// returns it; throws InputError at `where` when an earlier item of this kind has it.
  std::string Claim(const YamlValue& where, std::string name);

 private:
  std::string kind_;
  std::unordered_map<std::string, std::string> first_at_;  // name → "FILE:LINE:COL" of the first
};

}  // namespace ancfnet
