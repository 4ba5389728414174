#include "ancfnet/io/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "ancfnet/io/closest_name.hpp"

namespace ancfnet {
namespace {

[[noreturn]] void ThrowAt(const std::string& source, const YAML::Mark& mark,
                          std::string_view message) {
  throw InputError(fmt::format("{}:{}:{}: {}", source, mark.line + 1, mark.column + 1, message));
}

// The number written in `text` (an optional '+' sign allowed), or nullopt when it is not one.
template <typename T>
std::optional<T> ParseWhole(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// YAML's spellings of infinity and not-a-number (.inf, -.Inf, .NaN, ...).
bool IsYamlNonFinite(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("inf") != std::string::npos || lower.find("nan") != std::string::npos;
}

}  // namespace

YamlValue::YamlValue(YAML::Node node, std::string name, YAML::Mark mark,
                     std::shared_ptr<const std::string> source)
    : node_(std::move(node)), name_(std::move(name)), mark_(mark), source_(std::move(source)) {}

YamlValue YamlValue::Root(const YAML::Node& root, std::string source) {
  const YAML::Mark mark = root.Mark().is_null() ? YAML::Mark() : root.Mark();
  return YamlValue(root, "", mark, std::make_shared<const std::string>(std::move(source)));
}

YamlValue YamlValue::Child(const YAML::Node& node, std::string name,
                           const YAML::Mark& key_mark) const {
  // An empty value's mark points past the key (often at the next line): use the key's instead.
  const bool use_key = node.IsNull() || node.Mark().is_null();
  return YamlValue(node, std::move(name), use_key ? key_mark : node.Mark(), source_);
}

std::string YamlValue::Location() const {
  return fmt::format("{}:{}:{}", *source_, mark_.line + 1, mark_.column + 1);
}

std::string YamlValue::Describe() const {
  if (node_.IsNull()) return "an empty value";
  if (node_.IsMap()) return "a map";
  if (node_.IsSequence()) {
    if (node_.size() == 0) return "an empty list";
    return fmt::format("a list of {} item{}", node_.size(), node_.size() == 1 ? "" : "s");
  }
  if (!IsPlainScalar()) return fmt::format("the string \"{}\"", node_.Scalar());
  return fmt::format("'{}'", node_.Scalar());
}

void YamlValue::FailPlain(std::string_view message) const { ThrowAt(*source_, mark_, message); }

void YamlValue::Fail(std::string_view message) const {
  if (name_.empty()) FailPlain(message);
  FailPlain(fmt::format("{} (key '{}')", message, name_));
}

void YamlValue::FailExpected(std::string_view what) const {
  Fail(fmt::format("expected {}, got {}", what, Describe()));
}

bool YamlValue::IsPlainScalar() const {
  // yaml-cpp tags quoted scalars "!" and plain ones "?" (or an explicit tag).
  return node_.IsScalar() && node_.Tag() != "!";
}

double YamlValue::AsNumber() const {
  if (!IsPlainScalar()) FailExpected("a number");
  const std::optional<double> value = ParseWhole<double>(node_.Scalar());
  if (!value) FailExpected(IsYamlNonFinite(node_.Scalar()) ? "a finite number" : "a number");
  if (!std::isfinite(*value)) FailExpected("a finite number");
  return *value;
}

double YamlValue::AsPositive() const {
  const double value = AsNumber();
  if (!(value > 0.0)) FailExpected("a number > 0");
  return value;
}

double YamlValue::AsNonNegative() const {
  const double value = AsNumber();
  if (!(value >= 0.0)) FailExpected("a number ≥ 0");
  return value;
}

double YamlValue::AsNumberIn(double lo, double hi) const {
  const double value = AsNumber();
  if (!(value >= lo && value <= hi)) FailExpected(fmt::format("a number in [{}, {}]", lo, hi));
  return value;
}

int YamlValue::AsInt(int min, int max) const {
  std::string what = "an integer";
  if (min != INT_MIN && max != INT_MAX) {
    what += fmt::format(" in [{}, {}]", min, max);
  } else if (min != INT_MIN) {
    what += fmt::format(" ≥ {}", min);
  } else if (max != INT_MAX) {
    what += fmt::format(" ≤ {}", max);
  }
  if (!IsPlainScalar()) FailExpected(what);
  const std::optional<long long> value = ParseWhole<long long>(node_.Scalar());
  if (!value || *value < min || *value > max) FailExpected(what);
  return static_cast<int>(*value);
}

bool YamlValue::AsBool() const {
  if (IsPlainScalar()) {
    const std::string& text = node_.Scalar();
    if (text == "true" || text == "True" || text == "TRUE") return true;
    if (text == "false" || text == "False" || text == "FALSE") return false;
  }
  FailExpected("true or false");
}

std::string YamlValue::AsString() const {
  if (!node_.IsScalar() || node_.Scalar().empty()) FailExpected("a non-empty string");
  return node_.Scalar();
}

std::string YamlValue::AsName() const {
  const std::string name = AsString();
  constexpr std::size_t kMaxLength = 128;
  const auto unsafe = [](unsigned char c) { return c < 0x20 || c == 0x7f || c == ',' || c == '"'; };
  if (name.size() > kMaxLength)
    Fail(fmt::format("a name has at most {} characters (got {})", kMaxLength, name.size()));
  if (std::any_of(name.begin(), name.end(), unsafe))
    Fail("a name may not hold commas, double quotes, line breaks or other control characters "
         "(it heads CSV columns and keys summary.json)");
  if (name.front() == ' ' || name.back() == ' ') Fail("a name may not start or end with a blank");
  return name;
}

Vector3d YamlValue::AsVector3() const {
  if (!node_.IsSequence() || node_.size() != 3) FailExpected("a list of 3 numbers [x, y, z]");
  Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = Child(node_[i], fmt::format("{}[{}]", name_, i), mark_).AsNumber();
  return v;
}

std::size_t YamlValue::AsChoice(const std::vector<std::string_view>& names) const {
  const std::string text = AsString();
  const auto found = std::find(names.begin(), names.end(), text);
  if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
  const std::optional<std::string> closest = ClosestName(text, names);
  Fail(fmt::format("expected one of {}, got '{}'{}", fmt::join(names, ", "), text,
                   closest ? fmt::format("; did you mean '{}'?", *closest) : ""));
}

YamlMap YamlValue::AsMap() const {
  if (!node_.IsMap()) FailExpected("a map");
  std::vector<YamlMap::Entry> entries;
  std::unordered_map<std::string, std::size_t> index;  // key → entry, so large maps read in O(n)
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YAML::Mark key_mark = it->first.Mark().is_null() ? mark_ : it->first.Mark();
    if (!it->first.IsScalar()) ThrowAt(*source_, key_mark, "a key must be a plain name");
    const std::string key = it->first.Scalar();
    if (const auto [first, inserted] = index.emplace(key, entries.size()); !inserted)
      ThrowAt(*source_, key_mark,
              fmt::format("duplicate key '{}' (first given at line {})", key,
                          entries[first->second].key_mark.line + 1));
    entries.push_back({key, key_mark, Child(it->second, key, key_mark)});
  }
  return YamlMap(*this, std::move(entries));
}

std::vector<YamlValue> YamlValue::AsList(bool non_empty) const {
  if (!node_.IsSequence() || (non_empty && node_.size() == 0))
    FailExpected(non_empty ? "a non-empty list" : "a list");
  std::vector<YamlValue> items;
  items.reserve(node_.size());
  for (auto it = node_.begin(); it != node_.end(); ++it)
    items.push_back(Child(*it, fmt::format("{}[{}]", name_, items.size()), mark_));
  return items;
}

namespace {

std::string MapName(const YamlValue& map) {
  return map.name().empty() ? std::string("at the top level") : fmt::format("in '{}'", map.name());
}

}  // namespace

void YamlMap::CheckKeys(const std::vector<std::string_view>& allowed) const {
  for (const Entry& entry : entries_) {
    if (std::find(allowed.begin(), allowed.end(), entry.key) != allowed.end()) continue;
    ThrowAt(value_.source(), entry.key_mark,
            fmt::format("unknown key '{}' {}{}", entry.key, MapName(value_),
                        SuggestName(entry.key, allowed, "allowed keys")));
  }
}

std::optional<YamlValue> YamlMap::Find(std::string_view key) const {
  for (const Entry& entry : entries_)
    if (entry.key == key) return entry.value;
  return std::nullopt;
}

YamlValue YamlMap::Get(std::string_view key) const {
  if (std::optional<YamlValue> value = Find(key)) return *value;
  value_.FailPlain(fmt::format("missing required key '{}' {}", key, MapName(value_)));
}

}  // namespace ancfnet
