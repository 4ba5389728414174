#pragma once
/// @file Typed, checked access to a parsed YAML document. Every accessor either returns a valid
/// value or throws InputError with a one-line message "FILE:LINE:COL: what is wrong (key 'KEY')",
/// so a scene reader states only what it expects, never how to report it.

#include <climits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

class YamlMap;

/// A YAML node together with where it came from: the source name, its key (or "list[i]" for a
/// list item) and its position. Cheap to copy (YAML nodes are references).
class YamlValue {
 public:
  /// The root of a document read from `source` (a file name, or e.g. "<string>").
  static YamlValue Root(const YAML::Node& root, std::string source);

  /// A node inside this document: `name` is its key; `key_mark` the position of that key, used
  /// when the node itself carries none (an empty value).
  YamlValue Child(const YAML::Node& node, std::string name, const YAML::Mark& key_mark) const;

  const YAML::Node& node() const { return node_; }
  /// The key of this value ("elements", "cables[0]"); empty for the root.
  const std::string& name() const { return name_; }
  const std::string& source() const { return *source_; }
  bool IsMap() const { return node_.IsMap(); }
  bool IsSequence() const { return node_.IsSequence(); }
  bool IsScalar() const { return node_.IsScalar(); }

  /// A finite real number. YAML's .inf and .nan are refused; so are quoted strings.
  double AsNumber() const;
  /// A finite number > 0.
  double AsPositive() const;
  /// A finite number ≥ 0.
  double AsNonNegative() const;
  /// A finite number in [lo, hi].
  double AsNumberIn(double lo, double hi) const;
  /// An integer written as one (2.5 and 1e3 are refused) in [min, max].
  int AsInt(int min = INT_MIN, int max = INT_MAX) const;
  /// true or false (also True/TRUE/False/FALSE).
  bool AsBool() const;
  /// A non-empty scalar, as written.
  std::string AsString() const;
  /// The name of a thing (a probe, a target, a spring-damper, …): a scalar of at most 128
  /// characters without line breaks or other control characters, commas, double quotes or
  /// surrounding blanks, so that it can head a CSV column and key a JSON object as written.
  std::string AsName() const;
  /// A list of exactly three finite numbers [x, y, z].
  Vector3d AsVector3() const;
  /// The index in `names` of this scalar; the error lists the names and suggests the closest.
  std::size_t AsChoice(const std::vector<std::string_view>& names) const;
  /// The enumerator named by this scalar, from (name, value) pairs.
  template <typename E>
  E AsEnum(const std::vector<std::pair<std::string_view, E>>& choices) const {
    std::vector<std::string_view> names;
    for (const auto& choice : choices) names.push_back(choice.first);
    return choices[AsChoice(names)].second;
  }
  /// A map (refusing duplicate and non-scalar keys).
  YamlMap AsMap() const;
  /// A list (an empty value is not a list); with `non_empty`, one with at least one item.
  std::vector<YamlValue> AsList(bool non_empty = false) const;

  /// "FILE:LINE:COL" of this value (1-based line and column).
  std::string Location() const;
  /// How the value reads in a message: 'abc', a list of 2 items, a map, an empty value.
  std::string Describe() const;
  /// Throws InputError "FILE:LINE:COL: message (key 'NAME')".
  [[noreturn]] void Fail(std::string_view message) const;
  /// Throws InputError "FILE:LINE:COL: message" at the position of this value.
  [[noreturn]] void FailPlain(std::string_view message) const;
  /// Throws "FILE:LINE:COL: expected WHAT, got DESCRIPTION (key 'NAME')".
  [[noreturn]] void FailExpected(std::string_view what) const;

  /// Runs `action` (a call into the model-building API, say) and re-throws its InputError with
  /// this value's location and key, so that messages without a position get one.
  template <typename Action>
  decltype(auto) Locate(Action&& action) const;

 private:
  YamlValue(YAML::Node node, std::string name, YAML::Mark mark,
            std::shared_ptr<const std::string> source);
  bool IsPlainScalar() const;

  YAML::Node node_;
  std::string name_;
  YAML::Mark mark_;
  std::shared_ptr<const std::string> source_;
};

/// A YAML map with checked access to its keys.
class YamlMap {
 public:
  struct Entry {
    std::string key;
    YAML::Mark key_mark;  ///< position of the key (0-based, as yaml-cpp gives it)
    YamlValue value;
  };

  /// The map itself (for its location and name).
  const YamlValue& value() const { return value_; }
  /// The entries in file order.
  const std::vector<Entry>& entries() const { return entries_; }

  /// Throws for the first key that is not in `allowed`, suggesting the closest allowed key.
  void CheckKeys(const std::vector<std::string_view>& allowed) const;
  /// The value of `key`, or std::nullopt when the key is absent.
  std::optional<YamlValue> Find(std::string_view key) const;
  /// The value of a required `key`; throws "missing required key" at the map when absent.
  YamlValue Get(std::string_view key) const;

 private:
  friend class YamlValue;
  YamlMap(YamlValue value, std::vector<Entry> entries)
      : value_(std::move(value)), entries_(std::move(entries)) {}

  YamlValue value_;
  std::vector<Entry> entries_;
};

template <typename Action>
decltype(auto) YamlValue::Locate(Action&& action) const {
  try {
    return std::forward<Action>(action)();
  } catch (const InputError& error) {
    Fail(error.what());
  }
}

}  // namespace ancfnet
