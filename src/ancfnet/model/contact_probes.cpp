#include "ancfnet/model/contact_probes.hpp"

#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {

std::vector<ContactProbe> MakeContactProbes(const Model& model) {
  const ContactSpec& spec = model.contact();
  std::vector<ContactProbe> probes;
  if (spec.targets.empty()) return probes;
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const CableElementParameters& p = elements[e].parameters;
    const double radius = spec.cable_radius > 0.0
                              ? spec.cable_radius
                              : model.cables()[elements[e].cable].properties.radius;
    const bool capsules = spec.target_geometry == ContactSpec::TargetGeometry::kCapsules;
    const int n = capsules ? CalcCapsulesPerElement(spec, p.length, radius)
                           : CalcSpheresPerElement(spec, p.length, radius);
    for (int j = 0; j < n; ++j) {
      ContactProbe probe;
      probe.element = static_cast<Index>(e);
      probe.xi0 = capsules ? static_cast<double>(j) / n : (j + 0.5) / n;
      probe.xi1 = capsules ? static_cast<double>(j + 1) / n : probe.xi0;
      probe.shape0 = CalcHermiteShape(probe.xi0, p.length).s;
      probe.shape1 = CalcHermiteShape(probe.xi1, p.length).s;
      probe.radius = radius;
      probes.push_back(probe);
    }
  }
  for (std::size_t i = 0; i < model.point_masses().size(); ++i) {
    ContactProbe probe;
    probe.point_mass = static_cast<Index>(i);
    probe.radius = spec.point_mass_radius;
    probes.push_back(probe);
  }
  return probes;
}

Index CountContactPairs(const Model& model) {
  return static_cast<Index>(MakeContactProbes(model).size() * model.contact().targets.size());
}

}  // namespace ancfnet
