// ModelBuilder (model/model_builder.hpp): point masses, rigid bodies, the attachments of cable
// points to bodies and the spring-damper links between points.

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/fixed_attachment_stiffness.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

Index ModelBuilder::AddPointMass(const std::string& name, double mass, const Vector3d& position,
                                 const Vector3d& velocity) {
  CheckNameIsFree(name);
  RequireNonNegative(mass, "point mass");
  RequireFinite(position, "point mass position");
  RequireFinite(velocity, "point mass velocity");
  const Index dof = AddCoordinates(position);
  model_.initial_velocities_.segment<3>(dof) = velocity;
  model_.point_masses_.push_back({name, mass, dof});
  const Index index = static_cast<Index>(model_.point_masses_.size()) - 1;
  model_.names_.emplace(name, std::pair{Model::NamedKind::kPointMass, index});
  return index;
}

void ModelBuilder::SetPointMassVelocity(const std::string& name, const Vector3d& velocity) {
  RequireFinite(velocity, "point mass velocity");
  const Index mass = model_.FindPointMass(name);
  if (mass < 0) throw InputError(fmt::format("no point mass named '{}'", name));
  model_.initial_velocities_.segment<3>(model_.point_masses_[mass].dof) = velocity;
}

void ModelBuilder::FixPointMass(const std::string& name) {
  const Index mass = model_.FindPointMass(name);
  if (mass < 0) throw InputError(fmt::format("no point mass named '{}'", name));
  for (int k = 0; k < 3; ++k) model_.fixed_[model_.point_masses_[mass].dof + k] = true;
}

void ModelBuilder::MovePointMass(const std::string& name, const Vector3d& velocity) {
  RequireFinite(velocity, "velocity of a moving point mass");
  FixPointMass(name);
  const Index dof = model_.point_masses_[model_.FindPointMass(name)].dof;
  PrescribedBlock block;
  block.kind = PrescribedBlock::Kind::kTranslation;
  block.dof = dof;
  block.initial = model_.initial_positions_.segment<3>(dof);
  block.velocity = velocity;
  model_.prescribed_.push_back(block);
}

Index ModelBuilder::AddRigidBody(const RigidBodySpec& spec) {
  CheckNameIsFree(spec.name);
  RequirePositive(spec.mass, "body mass");
  ValidateInertia(spec.inertia, spec.name);
  ValidateRotation(spec.orientation, fmt::format("orientation of body '{}'", spec.name));
  RequireFinite(spec.position, "body position");
  RequireFinite(spec.velocity, "body velocity");
  RequireFinite(spec.angular_velocity, "body angular velocity");
  // Exactly orthonormal, so that round-off in the input does not act as a strain of R.
  const Matrix3d orientation = Eigen::Quaterniond(spec.orientation).normalized().toRotationMatrix();
  VectorXd initial(6);
  initial << spec.position, Vector3d::Zero();
  const Index dof = AddCoordinates(initial);
  const Vector3d w_B = spec.angular_velocity_in_world
                           ? Vector3d(orientation.transpose() * spec.angular_velocity)
                           : spec.angular_velocity;
  model_.initial_velocities_.segment<3>(dof) = spec.velocity;
  model_.initial_velocities_.segment<3>(dof + 3) = w_B;
  RigidBody body{.name = spec.name,
                 .mass = spec.mass,
                 .inertia = 0.5 * (spec.inertia + spec.inertia.transpose()),
                 .initial_orientation = orientation,
                 .motion = spec.motion,
                 .dof = dof};
  if (spec.motion != BodyMotion::kFree)
    for (int k = 0; k < 6; ++k) model_.fixed_[dof + k] = true;
  if (spec.motion == BodyMotion::kPrescribed) {
    // x = x₀ + v t and ψ = t ω_B (R_ref stays R₀): exp(t ω̃_B) is the exact constant-rate path.
    for (const auto& [first, rate] : {std::pair{dof, spec.velocity}, {dof + 3, w_B}}) {
      PrescribedBlock block;
      block.kind = PrescribedBlock::Kind::kTranslation;
      block.dof = first;
      block.initial = model_.initial_positions_.segment<3>(first);
      block.velocity = rate;
      model_.prescribed_.push_back(block);
    }
  }
  model_.rigid_bodies_.push_back(body);
  const Index index = static_cast<Index>(model_.rigid_bodies_.size()) - 1;
  model_.names_.emplace(body.name, std::pair{Model::NamedKind::kRigidBody, index});
  return index;
}

double ModelBuilder::PointMassOf(const CablePointRef& point) const {
  const Index mass = model_.FindPointMass(point.cable);
  if (mass >= 0) return model_.point_masses_[mass].mass;
  const MaterialPoint at = model_.LocateCablePoint(model_.FindCable(point.cable), point.s);
  const CableElementParameters& p = model_.elements_[at.element].parameters;
  return 0.5 * p.mass_per_length * p.length;
}

void ModelBuilder::AddBodyAttachment(const BodyAttachmentSpec& spec) {
  const Index b = model_.FindRigidBody(spec.body);
  if (b < 0) throw InputError(fmt::format("no rigid body named '{}'", spec.body));
  const RigidBody& body = model_.rigid_bodies_[b];
  BodyAttachment attachment{
      .name = spec.name, .point = model_.LocatePoint(spec.point.cable, spec.point.s), .body = b};
  if (spec.body_point) {
    RequireFinite(*spec.body_point, "attachment body point");
    attachment.body_point = *spec.body_point;
  } else {
    const Vector3d p0 = Model::Locate(attachment.point, model_.initial_positions_);
    const Vector3d x0 = model_.initial_positions_.segment<3>(body.position_dof());
    attachment.body_point = body.initial_orientation.transpose() * (p0 - x0);
  }
  // The free body's mass takes part in the pair's reduced mass; a fixed one is infinitely heavy.
  const double point_mass = PointMassOf(spec.point);
  const double body_mass =
      body.motion == BodyMotion::kFree ? body.mass : std::numeric_limits<double>::infinity();
  const double reduced =
      std::isinf(body_mass) ? point_mass : point_mass * body_mass / (point_mass + body_mass);
  if (spec.stiffness) {
    RequirePositive(*spec.stiffness, "attachment stiffness");
    attachment.stiffness = *spec.stiffness;
  } else {
    if (!(spec.time_step > 0.0))
      throw InputError(fmt::format(
          "attachment '{}': a fixed attachment (no stiffness given) takes its penalty stiffness "
          "from the time step, which is missing",
          spec.name));
    if (!(reduced > 0.0))
      throw InputError(fmt::format(
          "attachment '{}': the point has no mass; give the stiffness explicitly", spec.name));
    attachment.stiffness = CalcFixedAttachmentStiffness(reduced, spec.time_step);
  }
  if (spec.damping) {
    RequireNonNegative(*spec.damping, "attachment damping");
    attachment.damping = *spec.damping;
  } else if (!spec.stiffness) {
    attachment.damping = 2.0 * std::sqrt(attachment.stiffness * reduced);
  }
  model_.body_attachments_.push_back(attachment);
}

void ModelBuilder::AddSpringDamper(const std::string& name, const CablePointRef& first,
                                   const CablePointRef& second, const ConnectionLaw& law,
                                   std::optional<double> natural_length, double breaking_force) {
  ValidateConnectionLaw(law);
  RequireBreakingForce(breaking_force, "breaking force of a spring-damper");
  const auto cable_of = [&](const std::string& point) {
    return model_.FindPointMass(point) >= 0 ? Index{-1} : model_.FindCable(point);
  };
  SpringDamperLink link{.name = name,
                        .law = law,
                        .first = model_.LocatePoint(first.cable, first.s),
                        .second = model_.LocatePoint(second.cable, second.s),
                        .first_cable = cable_of(first.cable),
                        .second_cable = cable_of(second.cable),
                        .breaking_force = breaking_force};
  const double distance = (Model::Locate(link.second, model_.initial_positions_) -
                           Model::Locate(link.first, model_.initial_positions_))
                              .norm();
  link.natural_length = natural_length.value_or(distance);
  RequireNonNegative(link.natural_length, "natural length of a spring-damper");
  model_.links_.push_back(std::move(link));
}

}  // namespace ancfnet
