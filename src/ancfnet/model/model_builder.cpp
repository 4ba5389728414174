// ModelBuilder (model/model_builder.hpp): the model-wide settings (gravity, damping, contact,
// orbital frame), the coordinates and names every part shares, the nets' descriptions and Build.
// The parts themselves are added in add_cable.cpp, add_bodies.cpp, add_supports_and_loads.cpp,
// add_ideal_joint.cpp and add_clearance_joint.cpp.

#include "ancfnet/model/model_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"

namespace ancfnet {

void ModelBuilder::SetGravity(const Vector3d& gravity) {
  RequireFinite(gravity, "gravity");
  model_.gravity_ = gravity;
}

void ModelBuilder::CheckNameIsFree(const std::string& name) const {
  if (name.empty()) throw InputError("cables, point masses and bodies need a non-empty name");
  const auto found = model_.names_.find(name);
  if (found == model_.names_.end()) return;
  switch (found->second.first) {
    case Model::NamedKind::kCable:
      throw InputError(fmt::format("two cables are named '{}'", name));
    case Model::NamedKind::kPointMass:
      throw InputError(fmt::format("a point mass is already named '{}'", name));
    case Model::NamedKind::kRigidBody:
      throw InputError(fmt::format("a rigid body is already named '{}'", name));
  }
}

void ModelBuilder::SetRayleighDamping(const RayleighDamping& damping) {
  RequireNonNegative(damping.alpha, "Rayleigh damping α");
  RequireNonNegative(damping.beta, "Rayleigh damping β");
  model_.damping_.rayleigh = damping;
}

void ModelBuilder::SetModalDamping(const ModalDamping& damping) {
  if (damping.num_modes < 1)
    throw InputError(
        fmt::format("modal damping needs at least 1 mode (got {})", damping.num_modes));
  if (damping.ratios.empty() == damping.table.empty())
    throw InputError("modal damping needs either one ratio per mode or a table ζ(f), not both");
  if (!damping.ratios.empty() && static_cast<int>(damping.ratios.size()) != damping.num_modes)
    throw InputError(fmt::format("modal damping: {} modes but {} ratios", damping.num_modes,
                                 damping.ratios.size()));
  const auto check_ratio = [](double zeta) {
    if (!(zeta >= 0.0 && zeta < 1.0))
      throw InputError(fmt::format("a modal damping ratio must be in [0, 1) (got {})", zeta));
  };
  for (double zeta : damping.ratios) check_ratio(zeta);
  for (std::size_t j = 0; j < damping.table.size(); ++j) {
    const auto [f, zeta] = damping.table[j];
    check_ratio(zeta);
    if (!(f > 0.0 && std::isfinite(f)) || (j > 0 && !(f > damping.table[j - 1].first)))
      throw InputError(fmt::format(
          "modal damping table: frequencies must be positive and increasing (row {}: {} Hz)", j,
          f));
  }
  model_.damping_.modal = damping;
}

void ModelBuilder::SetContact(const ContactSpec& contact) {
  ValidateNormalLaw(contact.normal);
  if (contact.friction) ValidateFrictionLaw(*contact.friction);
  if (contact.points_per_element < 0 || contact.points_per_element > 1000)
    throw InputError("contact: points_per_element must be 0 (automatic) … 1000");
  if (contact.capsules_per_element < 0 || contact.capsules_per_element > 1000)
    throw InputError("contact: capsules_per_element must be 0 (automatic) … 1000");
  RequireNonNegative(contact.cable_radius, "contact cable radius");
  RequireNonNegative(contact.point_mass_radius, "contact point mass radius");
  RequireNonNegative(contact.penetration_increment, "contact penetration increment");
  for (const ContactTarget& t : contact.targets) {
    RequireFinite(t.point, "contact target position");
    switch (t.kind) {
      case ContactTarget::Kind::kPlane:
      case ContactTarget::Kind::kCylinder:
      case ContactTarget::Kind::kCapsule:
        if (std::abs(t.normal.norm() - 1.0) > 1e-6)
          throw InputError(
              fmt::format("contact target '{}': its normal or axis must be a unit "
                          "vector",
                          t.name));
        if (t.kind == ContactTarget::Kind::kCylinder) {
          RequirePositive(t.radius, "cylinder radius");
          RequirePositive(t.half_length, "cylinder half length");
        }
        if (t.kind == ContactTarget::Kind::kCapsule) {
          RequirePositive(t.radius, "capsule radius");
          RequireNonNegative(t.half_length, "capsule half length");
        }
        break;
      case ContactTarget::Kind::kMesh:
        if (t.mesh == nullptr)
          throw InputError(fmt::format("contact target '{}': a mesh target needs a mesh", t.name));
        break;
      case ContactTarget::Kind::kSphere:
        RequirePositive(t.radius, "sphere radius");
        break;
      case ContactTarget::Kind::kBox:
        for (int k = 0; k < 3; ++k) RequirePositive(t.half_extents[k], "box half extent");
        if (!(t.rotation.transpose() * t.rotation).isIdentity(1e-6))
          throw InputError(fmt::format("contact target '{}': not a rotation matrix", t.name));
        break;
    }
  }
  model_.contact_ = contact;
  for (ContactTarget& t : model_.contact_.targets)
    if (!t.body_name.empty()) {
      t.body = model_.FindRigidBody(t.body_name);
      if (t.body < 0)
        throw InputError(
            fmt::format("contact target '{}': no rigid body named '{}' (bodies must "
                        "be defined before the contact)",
                        t.name, t.body_name));
    }
  for (ContactTarget& t : model_.contact_.targets)
    if (t.kind == ContactTarget::Kind::kPlane || t.kind == ContactTarget::Kind::kCylinder ||
        t.kind == ContactTarget::Kind::kCapsule)
      t.normal.normalize();
}

void ModelBuilder::SetOrbitalFrame(double mean_motion) {
  RequirePositive(mean_motion, "orbital mean motion");
  model_.orbital_frame_ = mean_motion;
}

Index ModelBuilder::AddCoordinates(const VectorXd& initial_values) {
  const Index first = model_.num_dofs();
  const Index n = first + static_cast<Index>(initial_values.size());
  if (n > model_.initial_positions_.size()) {
    // Geometric growth: a net of N nodes is appended in O(N), not O(N²) copies.
    const Index capacity = std::max<Index>(n, 2 * model_.initial_positions_.size());
    model_.initial_positions_.conservativeResize(capacity);
    model_.initial_velocities_.conservativeResize(capacity);
  }
  model_.initial_positions_.segment(first, initial_values.size()) = initial_values;
  model_.initial_velocities_.segment(first, initial_values.size()).setZero();
  model_.num_dofs_ = n;
  model_.fixed_.resize(n, false);
  return first;
}

void ModelBuilder::AddNetDescription(const Net& net) {
  for (const Net& other : model_.nets_)
    if (other.name == net.name) throw InputError(fmt::format("two nets are named '{}'", net.name));
  model_.nets_.push_back(net);
}

Model ModelBuilder::Build() const {
  if (model_.cables_.empty() && model_.point_masses_.empty() && model_.rigid_bodies_.empty())
    throw InputError("the model has no cable, no point mass and no rigid body");
  if (model_.damping_.modal.num_modes > 0 && model_.has_free_bodies())
    throw InputError(
        "modal damping needs the modes of the model, which free rigid bodies do not have; use "
        "Rayleigh damping or make the bodies fixed");
  Model model = model_;
  model.initial_positions_.conservativeResize(model.num_dofs_);
  model.initial_velocities_.conservativeResize(model.num_dofs_);
  // A fixed coordinate does not move, unless it belongs to a moving point mass.
  for (Index i = 0; i < model.num_dofs(); ++i)
    if (model.fixed_[i]) model.initial_velocities_[i] = 0.0;
  ApplyPrescribedMotion(model.prescribed_, 0.0, nullptr, &model.initial_velocities_, nullptr);
  return model;
}

}  // namespace ancfnet
