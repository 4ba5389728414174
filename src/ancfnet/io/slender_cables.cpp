#include "ancfnet/io/slender_cables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace ancfnet {

void CheckSlenderCable(const Section& section, double length, std::string_view owner,
                       const YamlValue& where) {
  const double diameter = 2.0 * std::sqrt(section.area / std::numbers::pi);
  if (diameter <= length || !(length > 0.0)) return;
  where.Fail(fmt::format(
      "a section {:.3g} m thick (the diameter of its area) is thicker than {} is long ({:.3g} m); "
      "a cable must be slender: check the unit of the section",
      diameter, owner, length));
}

}  // namespace ancfnet
