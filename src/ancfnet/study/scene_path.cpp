#include "ancfnet/study/scene_path.hpp"

#include <fmt/format.h>

#include <cctype>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/closest_name.hpp"

namespace ancfnet {
namespace {

bool IsNameCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

bool IsIndex(std::string_view word) {
  for (const char c : word)
    if (std::isdigit(static_cast<unsigned char>(c)) == 0) return false;
  return !word.empty() && word.size() <= 9;
}

// The path up to (not including) step `end`, as the user wrote it, for messages.
std::string Prefix(const std::vector<ScenePathStep>& steps, std::size_t end) {
  std::string text;
  for (std::size_t i = 0; i < end; ++i) {
    const ScenePathStep& step = steps[i];
    if (step.kind == ScenePathStep::Kind::kKey)
      text += (text.empty() ? "" : ".") + step.key;
    else if (step.kind == ScenePathStep::Kind::kIndex)
      text += fmt::format("[{}]", step.index);
    else
      text += "[" + step.key + "]";
  }
  return text.empty() ? std::string("the top level") : "'" + text + "'";
}

YAML::Node FindKey(const YAML::Node& map, const std::string& key, const std::string& where,
                   std::string_view scene_name) {
  std::vector<std::string> keys;
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) continue;
    keys.push_back(entry.first.Scalar());
    if (keys.back() == key) return entry.second;
  }
  const std::vector<std::string_view> candidates(keys.begin(), keys.end());
  throw InputError(fmt::format("the scene {} has no key '{}' in {}{}", scene_name, key, where,
                               SuggestName(key, candidates, "keys there")));
}

YAML::Node FindNamedItem(const YAML::Node& list, const std::string& name, const std::string& where,
                         std::string_view scene_name) {
  std::vector<std::string> names;
  for (const YAML::Node& item : list) {
    const YAML::Node item_name = item.IsMap() ? item["name"] : YAML::Node();
    if (!item_name || !item_name.IsScalar()) continue;
    names.push_back(item_name.Scalar());
    if (names.back() == name) return item;
  }
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  throw InputError(fmt::format("the scene {} has no item named '{}' in {}{}", scene_name, name,
                               where, SuggestName(name, candidates, "names there")));
}

}  // namespace

ScenePath ScenePath::Parse(std::string_view text) {
  ScenePath path;
  path.text_ = std::string(text);
  const auto refuse = [&](std::string_view why) {
    throw InputError(fmt::format(
        "'{}' is not a scene path ({}; expected keys joined by '.', list items as [INDEX] or "
        "[NAME], e.g. nets[0].velocity[2])",
        text, why));
  };
  std::size_t at = 0;
  const auto read_word = [&] {
    const std::size_t start = at;
    while (at < text.size() && IsNameCharacter(text[at])) ++at;
    return text.substr(start, at - start);
  };
  bool expect_key = true;
  while (at < text.size() || expect_key) {
    if (expect_key) {
      const std::string_view key = read_word();
      if (key.empty()) refuse(fmt::format("a key is missing at character {}", at + 1));
      path.steps_.push_back({ScenePathStep::Kind::kKey, std::string(key), 0});
      expect_key = false;
    } else if (text[at] == '.') {
      ++at;
      expect_key = true;
    } else if (text[at] == '[') {
      ++at;
      const std::string_view word = read_word();
      if (word.empty() || at >= text.size() || text[at] != ']')
        refuse(fmt::format("a '[' without an index or name and ']' at character {}", at + 1));
      ++at;
      if (IsIndex(word))
        path.steps_.push_back({ScenePathStep::Kind::kIndex, "", std::stoul(std::string(word))});
      else
        path.steps_.push_back({ScenePathStep::Kind::kName, std::string(word), 0});
    } else {
      refuse(fmt::format("unexpected '{}' at character {}", text[at], at + 1));
    }
  }
  return path;
}

YAML::Node ScenePath::Find(const YAML::Node& root, std::string_view scene_name) const {
  // reset() rebinds `node`; assigning to it would overwrite the tree's values.
  YAML::Node node;
  node.reset(root);
  for (std::size_t i = 0; i < steps_.size(); ++i) {
    const ScenePathStep& step = steps_[i];
    const std::string where = Prefix(steps_, i);
    if (step.kind == ScenePathStep::Kind::kKey) {
      if (!node.IsMap())
        throw InputError(fmt::format("{} of the scene {} is not a map, so it has no key '{}'",
                                     where, scene_name, step.key));
      node.reset(FindKey(node, step.key, where, scene_name));
      continue;
    }
    if (!node.IsSequence())
      throw InputError(fmt::format("{} of the scene {} is not a list", where, scene_name));
    if (step.kind == ScenePathStep::Kind::kName) {
      node.reset(FindNamedItem(node, step.key, where, scene_name));
    } else {
      if (step.index >= node.size())
        throw InputError(fmt::format("the scene {} has no item [{}] in {} (a list of {} items)",
                                     scene_name, step.index, where, node.size()));
      const YAML::Node& list = node;  // const: operator[] must not add an item
      node.reset(list[step.index]);
    }
  }
  return node;
}

}  // namespace ancfnet
