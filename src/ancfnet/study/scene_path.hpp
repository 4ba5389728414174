#pragma once
/// @file A path to one value of a scene file's YAML tree, as a study names the value it varies:
/// keys joined by dots, list items by index or by name, e.g. `contact.friction.static`,
/// `nets[0].velocity[2]`, `bodies[target].angular_velocity[2]` (docs/studies.md).

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ancfnet {

/// One step of a ScenePath: a map key, or a list item by index or by its `name`.
struct ScenePathStep {
  enum class Kind { kKey, kIndex, kName };
  Kind kind = Kind::kKey;
  std::string key;  ///< the key (kKey) or the item's name (kName)
  std::size_t index = 0;
};

class ScenePath {
 public:
  /// Parses `text`: KEY ('.' KEY | '[' INDEX ']' | '[' NAME ']')*, keys and names of letters,
  /// digits, '_' and '-'. Throws InputError (without a position) for anything else.
  static ScenePath Parse(std::string_view text);

  const std::string& text() const { return text_; }
  const std::vector<ScenePathStep>& steps() const { return steps_; }

  /// The node of `root` this path names; it shares the tree (assigning to it changes `root`).
  /// Throws InputError (without a position) "no key 'K' in 'A.B' (did you mean 'X'?)", "no item
  /// [3] in 'A' (a list of 2 items)", "no item named 'N' in 'A'", "'A' is not a map" or "'A'
  /// is not a list", `scene_name` naming the scene in the message.
  YAML::Node Find(const YAML::Node& root, std::string_view scene_name) const;

 private:
  std::string text_;
  std::vector<ScenePathStep> steps_;
};

}  // namespace ancfnet
