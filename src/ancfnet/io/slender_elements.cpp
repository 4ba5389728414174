#include "ancfnet/io/slender_elements.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace ancfnet {

void CheckSlenderElements(const Section& section, double element_length, std::string_view owner,
                          const YamlValue& where) {
  const double diameter = 2.0 * std::sqrt(section.area / std::numbers::pi);
  // A zero length is the model builder's to refuse, with its own reason.
  if (diameter <= element_length || !(element_length > 0.0)) return;
  where.Fail(fmt::format(
      "a section {:.3g} m thick (the diameter of its area) is thicker than the {:.3g} m elements "
      "of {} are long; cable elements must be slender: check the unit of the section, or use "
      "fewer elements",
      diameter, element_length, owner));
}

}  // namespace ancfnet
