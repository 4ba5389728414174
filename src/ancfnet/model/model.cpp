#include "ancfnet/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "ancfnet/common/error.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {

double Model::total_mass() const {
  double mass = 0.0;
  for (const Cable& cable : cables_) mass += cable.properties.mass_per_length * cable.length;
  for (const PointMass& point : point_masses_) mass += point.mass;
  for (const RigidBody& body : rigid_bodies_) mass += body.mass;
  return mass;
}

Index Model::num_constraint_equations() const {
  Index n = 0;
  for (const IdealJoint& joint : ideal_joints_) n += joint.num_equations();
  return n;
}

bool Model::has_free_bodies() const {
  for (const RigidBody& body : rigid_bodies_)
    if (body.motion == BodyMotion::kFree) return true;
  return false;
}

Index Model::FindNamed(const std::string& name, NamedKind kind) const {
  const auto found = names_.find(name);
  return found != names_.end() && found->second.first == kind ? found->second.second : -1;
}

Index Model::FindRigidBody(const std::string& name) const {
  return FindNamed(name, NamedKind::kRigidBody);
}

Index Model::FindPointMass(const std::string& name) const {
  return FindNamed(name, NamedKind::kPointMass);
}

Index Model::FindCable(const std::string& name) const {
  if (const Index cable = FindNamed(name, NamedKind::kCable); cable >= 0) return cable;
  std::string names;
  for (const Cable& cable : cables_) names += (names.empty() ? "" : ", ") + cable.name;
  throw InputError(fmt::format("no cable named '{}' (cables: {})", name, names));
}

MaterialPoint Model::LocateCablePoint(Index cable_index, double s) const {
  if (!(s >= 0.0 && s <= 1.0))
    throw InputError(fmt::format("cable fraction s must be in [0, 1] (got {})", s));
  const Cable& cable = cables_[cable_index];
  const double position = s * static_cast<double>(cable.num_elements);
  const Index local = std::min<Index>(static_cast<Index>(std::floor(position)),
                                      cable.num_elements - 1);
  return {cable.first_element + local, position - static_cast<double>(local)};
}

Index Model::LocateCableNode(Index cable_index, double s) const {
  const Cable& cable = cables_[cable_index];
  const double position = s * static_cast<double>(cable.num_elements);
  const double nearest = std::round(position);
  if (!(s >= 0.0 && s <= 1.0) || std::abs(position - nearest) > 1e-9 * cable.num_elements)
    throw InputError(fmt::format(
        "s = {} on cable '{}' is not at a node (nodes are at multiples of 1/{})", s, cable.name,
        cable.num_elements));
  return cable.first_node + static_cast<Index>(nearest);
}

Vector12d Model::Gather(const CableElement& element, const VectorXd& x) const {
  Vector12d e;
  for (int i = 0; i < kCableElementDofs; ++i) e[i] = x[element.dofs[i]];
  return e;
}

Vector24d Model::Gather(const BeamElement& element, const VectorXd& x) const {
  Vector24d e;
  for (int i = 0; i < kBeamElementDofs; ++i) e[i] = x[element.dofs[i]];
  return e;
}

Vector3d Model::Interpolate(const MaterialPoint& point, const VectorXd& x) const {
  const CableElement& element = elements_[point.element];
  const HermiteShape shape = CalcHermiteShape(point.xi, element.parameters.length);
  return InterpolatePosition(Gather(element, x), shape.s);
}

Vector3d Model::Locate(const PointLocation& point, const VectorXd& x) {
  Vector3d r = Vector3d::Zero();
  for (int b = 0; b < point.num_blocks; ++b) r += point.weight[b] * x.segment<3>(point.dof[b]);
  return r;
}

PointLocation Model::LocateMaterialPoint(const MaterialPoint& point) const {
  const CableElement& element = elements_[point.element];
  const HermiteShape shape = CalcHermiteShape(point.xi, element.parameters.length);
  PointLocation location;
  location.num_blocks = 4;
  for (int b = 0; b < 4; ++b) {
    location.dof[b] = element.dofs[3 * b];
    location.weight[b] = shape.s[b];
  }
  return location;
}

PointLocation Model::LocatePoint(const std::string& name, double s) const {
  const Index mass = FindPointMass(name);
  if (mass >= 0) return {.num_blocks = 1, .dof = {point_masses_[mass].dof}, .weight = {1.0}};
  return LocateMaterialPoint(LocateCablePoint(FindCable(name), s));
}

}  // namespace ancfnet
