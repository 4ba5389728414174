#include "ancfnet/io/contact_period_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "ancfnet/model/contact_probes.hpp"

namespace ancfnet {

void CheckContactPeriod(const Model& model, double time_step, const YamlValue& stiffness) {
  const NormalLaw& law = model.contact().normal;
  const std::vector<ContactProbe> probes = MakeContactProbes(model);
  std::vector<int> per_element(model.elements().size(), 0);
  for (const ContactProbe& probe : probes)
    if (probe.element >= 0) ++per_element[probe.element];
  double shortest = std::numeric_limits<double>::infinity();
  double lightest = 0.0;
  for (const ContactProbe& probe : probes) {
    double mass = 0.0;
    if (probe.element >= 0) {
      const CableElementParameters& p = model.elements()[probe.element].parameters;
      mass = p.mass_per_length * p.length / per_element[probe.element];
    } else {
      mass = model.point_masses()[probe.point_mass].mass;
    }
    const double depth = 0.1 * probe.radius;
    const double k = law.exponent * law.stiffness * std::pow(depth, law.exponent - 1.0);
    if (!(mass > 0.0 && k > 0.0)) continue;
    const double period = 2.0 * std::numbers::pi * std::sqrt(mass / k);
    if (period < shortest) {
      shortest = period;
      lightest = mass;
    }
  }
  if (shortest >= kMinContactPeriodSteps * time_step) return;
  stiffness.Fail(fmt::format(
      "a contact of the lightest contact point ({:.3g} kg) would last 2π √(m/k) = {:.3g} s, less "
      "than 1/{:.0f} of the time step {} s: no step could resolve it; check the stiffness and its "
      "unit (N/m^{})",
      lightest, shortest, 1.0 / kMinContactPeriodSteps, time_step, law.exponent));
}

}  // namespace ancfnet
