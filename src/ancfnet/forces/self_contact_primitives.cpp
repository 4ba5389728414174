#include "ancfnet/forces/self_contact_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {
namespace {

double CableRadius(const Model& model, const CableElement& element) {
  const ContactSpec& spec = model.contact();
  return spec.cable_radius > 0.0 ? spec.cable_radius
                                 : model.cables()[element.cable].properties.radius;
}

int PrimitivesPerElement(const ContactSpec& spec, double length, double radius) {
  return spec.self_geometry == ContactSpec::SelfGeometry::kSpheres
             ? CalcSpheresPerElement(spec, length, radius)
             : CalcCapsulesPerElement(spec, length, radius);
}

// Union–find over junction nodes.
int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<SelfContactPrimitive> MakeSelfContactPrimitives(const Model& model) {
  const ContactSpec& spec = model.contact();
  std::vector<SelfContactPrimitive> primitives;
  if (!spec.self_contact) return primitives;
  const bool spheres = spec.self_geometry == ContactSpec::SelfGeometry::kSpheres;
  const auto& elements = model.elements();
  for (const Cable& cable : model.cables()) {
    double arc = 0.0;
    for (Index e = cable.first_element; e < cable.first_element + cable.num_elements; ++e) {
      const CableElementParameters& p = elements[e].parameters;
      const double radius = CableRadius(model, elements[e]);
      const int n = PrimitivesPerElement(spec, p.length, radius);
      for (int j = 0; j < n; ++j) {
        SelfContactPrimitive c;
        c.element = e;
        c.cable = elements[e].cable;
        c.xi0 = spheres ? (j + 0.5) / n : static_cast<double>(j) / n;
        c.xi1 = spheres ? c.xi0 : static_cast<double>(j + 1) / n;
        c.shape0 = CalcHermiteShape(c.xi0, p.length).s;
        c.shape1 = CalcHermiteShape(c.xi1, p.length).s;
        c.radius = radius;
        c.arc0 = arc + c.xi0 * p.length;
        c.arc1 = arc + c.xi1 * p.length;
        c.owner = e;
        if (!spheres && c.arc0 > 0.0) {
          c.previous = static_cast<int>(primitives.size()) - 1;
          primitives.back().next = static_cast<int>(primitives.size());
        }
        primitives.push_back(c);
      }
      arc += p.length;
    }
  }
  for (std::size_t i = 0; i < model.point_masses().size(); ++i) {
    SelfContactPrimitive c;
    c.point_mass = static_cast<Index>(i);
    c.radius = spec.point_mass_radius;
    c.owner = static_cast<Index>(elements.size() + i);
    primitives.push_back(c);
  }
  return primitives;
}

SelfContactFilter::SelfContactFilter(const Model& model,
                                     const std::vector<SelfContactPrimitive>& primitives)
    : primitives_(&primitives), cables_(&model.cables()) {
  const auto& cables = model.cables();
  const Index num_cables = static_cast<Index>(cables.size());
  const Index num_points = static_cast<Index>(model.point_masses().size());
  // Junction nodes: 2 per cable (its ends), then one per point mass.
  std::vector<int> parent(2 * num_cables + num_points);
  std::iota(parent.begin(), parent.end(), 0);
  auto join = [&](int a, int b) { parent[Root(parent, a)] = Root(parent, b); };
  std::unordered_map<Index, Index> point_mass_at;  // first coordinate → point mass
  for (Index m = 0; m < num_points; ++m) point_mass_at.emplace(model.point_masses()[m].dof, m);
  // The node of a located point: a cable end or a point mass, or −1.
  auto node_of = [&](const PointLocation& point, Index cable) -> int {
    if (cable < 0) {
      const auto it = point_mass_at.find(point.dof[0]);
      return it == point_mass_at.end() ? -1 : static_cast<int>(2 * num_cables + it->second);
    }
    const Cable& c = cables[cable];
    for (int end = 0; end < 2; ++end) {
      const Index node = c.first_node + end * c.num_elements;
      for (int b = 0; b < point.num_blocks; ++b)
        if (point.dof[b] == model.NodePositionDof(node) && std::abs(point.weight[b] - 1.0) < 1e-12)
          return static_cast<int>(2 * cable + end);
    }
    return -1;
  };
  for (const SpringDamperLink& link : model.links()) {
    const int a = node_of(link.first, link.first_cable);
    const int b = node_of(link.second, link.second_cable);
    if (a >= 0 && b >= 0) join(a, b);
  }
  // Ideal knots: cable ends sharing their position coordinates (with a point mass's, maybe).
  std::unordered_map<Index, int> end_at_position;
  for (Index m = 0; m < num_points; ++m)
    end_at_position.emplace(model.point_masses()[m].dof, static_cast<int>(2 * num_cables + m));
  for (Index c = 0; c < num_cables; ++c)
    for (int end = 0; end < 2; ++end) {
      const int node = static_cast<int>(2 * c + end);
      const auto [it, inserted] = end_at_position.emplace(
          model.NodePositionDof(cables[c].first_node + end * cables[c].num_elements), node);
      if (!inserted) join(node, it->second);
    }
  cable_length_.resize(num_cables);
  cable_end_junction_.resize(num_cables);
  for (Index c = 0; c < num_cables; ++c) {
    cable_length_[c] = 0.0;
    for (Index e = cables[c].first_element; e < cables[c].first_element + cables[c].num_elements;
         ++e)
      cable_length_[c] += model.elements()[e].parameters.length;
    for (int end = 0; end < 2; ++end)
      cable_end_junction_[c][end] = Root(parent, static_cast<int>(2 * c + end));
  }
  point_mass_junction_.resize(num_points);
  for (Index m = 0; m < num_points; ++m)
    point_mass_junction_[m] = Root(parent, static_cast<int>(2 * num_cables + m));
}

double SelfContactFilter::ArcToEnd(const SelfContactPrimitive& p, int end) const {
  if (p.cable < 0) return 0.0;
  return end == 0 ? p.arc0 : cable_length_[p.cable] - p.arc1;
}

bool SelfContactFilter::AtEndElement(const SelfContactPrimitive& p, int end) const {
  if (p.cable < 0) return true;
  const Cable& cable = (*cables_)[p.cable];
  return p.element ==
         (end == 0 ? cable.first_element : cable.first_element + cable.num_elements - 1);
}

bool SelfContactFilter::Excluded(int a, int b) const {
  const SelfContactPrimitive& pa = (*primitives_)[a];
  const SelfContactPrimitive& pb = (*primitives_)[b];
  const double reach = 2.0 * (pa.radius + pb.radius);
  if (pa.cable >= 0 && pa.cable == pb.cable)
    return std::max(pa.arc0, pb.arc0) - std::min(pa.arc1, pb.arc1) < reach;
  // Junctions of each: a cable's two ends, or a point mass's own.
  auto junctions = [&](const SelfContactPrimitive& p) -> std::array<int, 2> {
    if (p.cable < 0) return {point_mass_junction_[p.point_mass], -1};
    return cable_end_junction_[p.cable];
  };
  const std::array<int, 2> ja = junctions(pa), jb = junctions(pb);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (ja[i] >= 0 && ja[i] == jb[j] &&
          ((AtEndElement(pa, i) && AtEndElement(pb, j)) ||
           ArcToEnd(pa, i) + ArcToEnd(pb, j) < reach))
        return true;
  return false;
}

}  // namespace ancfnet
