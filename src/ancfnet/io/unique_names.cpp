#include "ancfnet/io/unique_names.hpp"

#include <fmt/format.h>

namespace ancfnet {

std::string UniqueNames::Claim(const YamlValue& where, std::string name) {
  const auto [first, inserted] = first_at_.emplace(name, where.Location());
  if (!inserted)
    where.Fail(fmt::format("two {} are named '{}' (the first at {})", kind_, name, first->second));
  return name;
}

}  // namespace ancfnet
