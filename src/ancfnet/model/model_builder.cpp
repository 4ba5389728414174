#include "ancfnet/model/model_builder.hpp"

#include <cmath>
#include <fmt/format.h>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

void RequireFinite(const Vector3d& v, const char* what) {
  if (!v.allFinite())
    throw InputError(fmt::format("{} must be finite (got [{}, {}, {}])", what, v.x(), v.y(), v.z()));
}

void RequirePositive(double value, const char* what) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(fmt::format("{} must be > 0 (got {})", what, value));
}

void RequireNonNegative(double value, const char* what) {
  if (!(value >= 0.0 && std::isfinite(value)))
    throw InputError(fmt::format("{} must be ≥ 0 (got {})", what, value));
}

void ValidateProperties(const CableProperties& p) {
  RequirePositive(p.axial_stiffness, "axial stiffness EA");
  RequireNonNegative(p.bending_stiffness, "bending stiffness EI");
  RequirePositive(p.mass_per_length, "mass per length ρA");
  RequireNonNegative(p.axial_damping_time, "axial damping time");
  RequireNonNegative(p.bending_damping_time, "bending damping time");
  RequireNonNegative(p.radius, "radius");
  for (int n : {p.axial_gauss_points, p.bending_gauss_points})
    if (n < 1 || n > 8) throw InputError(fmt::format("Gauss points must be 1 … 8 (got {})", n));
}

}  // namespace

void ModelBuilder::SetGravity(const Vector3d& gravity) {
  RequireFinite(gravity, "gravity");
  model_.gravity_ = gravity;
}

Index ModelBuilder::AddCable(const CableSpec& spec) {
  if (spec.name.empty()) throw InputError("a cable needs a non-empty name");
  for (const Cable& cable : model_.cables_)
    if (cable.name == spec.name)
      throw InputError(fmt::format("two cables are named '{}'", spec.name));
  RequireFinite(spec.start, "cable start");
  RequireFinite(spec.end, "cable end");
  if (spec.num_elements < 1)
    throw InputError(fmt::format("a cable needs at least 1 element (got {})", spec.num_elements));
  const double length = (spec.end - spec.start).norm();
  if (!(length > 0.0))
    throw InputError(fmt::format("cable '{}' has zero length (start equals end)", spec.name));
  ValidateProperties(spec.properties);

  Cable cable;
  cable.name = spec.name;
  cable.first_node = model_.num_nodes();
  cable.first_element = static_cast<Index>(model_.elements_.size());
  cable.num_elements = spec.num_elements;
  cable.length = length;
  cable.properties = spec.properties;
  const Index cable_index = static_cast<Index>(model_.cables_.size());
  model_.cables_.push_back(cable);

  // Nodes: positions along the segment, slopes equal to the unit tangent (stress-free).
  const Index num_nodes = spec.num_elements + 1;
  const Vector3d tangent = (spec.end - spec.start) / length;
  const Index first_dof = Model::NodeDof(cable.first_node);
  model_.initial_positions_.conservativeResize(first_dof + num_nodes * kCableNodeDofs);
  model_.initial_velocities_.conservativeResizeLike(
      VectorXd::Zero(first_dof + num_nodes * kCableNodeDofs));
  for (Index i = 0; i < num_nodes; ++i) {
    const double s = static_cast<double>(i) / spec.num_elements;
    model_.initial_positions_.segment<3>(first_dof + kCableNodeDofs * i) =
        spec.start + s * (spec.end - spec.start);
    model_.initial_positions_.segment<3>(first_dof + kCableNodeDofs * i + 3) = tangent;
  }
  model_.fixed_.resize(model_.initial_positions_.size(), false);

  const CableProperties& p = spec.properties;
  for (Index i = 0; i < spec.num_elements; ++i) {
    CableElement element;
    element.cable = cable_index;
    for (int k = 0; k < kCableElementDofs; ++k)
      element.dofs[k] = first_dof + kCableNodeDofs * i + k;
    CableElementParameters& ep = element.parameters;
    ep.length = length / spec.num_elements;
    ep.axial_stiffness = p.axial_stiffness;
    ep.bending_stiffness = p.bending_stiffness;
    ep.mass_per_length = p.mass_per_length;
    ep.axial_damping_time = p.axial_damping_time;
    ep.bending_damping_time = p.bending_damping_time;
    ep.tension_only = p.tension_only;
    ep.axial_gauss_points = p.axial_gauss_points;
    ep.bending_gauss_points = p.bending_gauss_points;
    model_.elements_.push_back(element);
  }
  return cable_index;
}

Index ModelBuilder::LocateNode(const CablePointRef& at) const {
  return model_.LocateCableNode(model_.FindCable(at.cable), at.s);
}

void ModelBuilder::FixCoordinates(const CablePointRef& at, const CoordinateMask& mask) {
  const Index first = Model::NodeDof(LocateNode(at));
  for (int k = 0; k < kCableNodeDofs; ++k)
    if (mask[k]) model_.fixed_[first + k] = true;
}

void ModelBuilder::AddClamp(const CablePointRef& at) {
  FixCoordinates(at, {true, true, true, true, true, true});
}

void ModelBuilder::AddPin(const CablePointRef& at) {
  FixCoordinates(at, {true, true, true, false, false, false});
}

void ModelBuilder::AddPointForce(const CablePointRef& at, const Vector3d& force) {
  RequireFinite(force, "force");
  const MaterialPoint point = model_.LocateCablePoint(model_.FindCable(at.cable), at.s);
  model_.point_forces_.push_back({point, force});
}

void ModelBuilder::AddPointMoment(const CablePointRef& at, const Vector3d& moment) {
  RequireFinite(moment, "moment");
  model_.point_moments_.push_back({LocateNode(at), moment});
}

void ModelBuilder::AddDistributedLoad(const std::string& cable, const Vector3d& force_per_length) {
  RequireFinite(force_per_length, "force per length");
  model_.distributed_loads_.push_back({model_.FindCable(cable), force_per_length});
}

void ModelBuilder::SetInitialVelocity(const std::string& cable_name, const Vector3d& velocity,
                                      const Vector3d& angular_velocity, const Vector3d& center) {
  RequireFinite(velocity, "initial velocity");
  RequireFinite(angular_velocity, "initial angular velocity");
  RequireFinite(center, "rotation centre");
  const Cable& cable = model_.cables_[model_.FindCable(cable_name)];
  for (Index i = 0; i <= cable.num_elements; ++i) {
    const Index dof = Model::NodeDof(cable.first_node + i);
    const Vector3d r = model_.initial_positions_.segment<3>(dof);
    const Vector3d slope = model_.initial_positions_.segment<3>(dof + 3);
    // Rigid motion: ṙ = v + ω × (r − c), ṙ' = ω × r'.
    model_.initial_velocities_.segment<3>(dof) = velocity + angular_velocity.cross(r - center);
    model_.initial_velocities_.segment<3>(dof + 3) = angular_velocity.cross(slope);
  }
}

Model ModelBuilder::Build() const {
  if (model_.cables_.empty()) throw InputError("the model has no cable");
  Model model = model_;
  // A fixed coordinate cannot move: its initial velocity is zero.
  for (Index i = 0; i < model.num_dofs(); ++i)
    if (model.fixed_[i]) model.initial_velocities_[i] = 0.0;
  return model;
}

}  // namespace ancfnet
