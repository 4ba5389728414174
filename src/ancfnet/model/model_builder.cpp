#include "ancfnet/model/model_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/fixed_attachment_stiffness.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {
namespace {

void RequireFinite(const Vector3d& v, const char* what) {
  if (!v.allFinite())
    throw InputError(
        fmt::format("{} must be finite (got [{}, {}, {}])", what, v.x(), v.y(), v.z()));
}

void RequirePositive(double value, const char* what) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(fmt::format("{} must be > 0 (got {})", what, value));
}

// > 0, infinity allowed (never breaks); NaN refused.
void RequireBreakingForce(double value, const char* what) {
  if (!(value > 0.0)) throw InputError(fmt::format("{} must be > 0 (got {})", what, value));
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
  RequireNonNegative(p.rope_smoothing_strain, "rope smoothing strain");
  for (int n : {p.axial_gauss_points, p.bending_gauss_points})
    if (n < 1 || n > 8) throw InputError(fmt::format("Gauss points must be 1 … 8 (got {})", n));
}

}  // namespace

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
  model_.initial_positions_.conservativeResize(n);
  model_.initial_positions_.tail(initial_values.size()) = initial_values;
  model_.initial_velocities_.conservativeResizeLike(VectorXd::Zero(n));
  model_.fixed_.resize(n, false);
  return first;
}

Index ModelBuilder::EndPositionDof(const std::string& knot, const Vector3d& position,
                                   const char* which) {
  if (knot.empty()) return AddCoordinates(position);
  const Index mass = model_.FindPointMass(knot);
  if (mass < 0)
    throw InputError(fmt::format("no point mass named '{}' for the cable {}", knot, which));
  const Index dof = model_.point_masses_[mass].dof;
  const Vector3d at = model_.initial_positions_.segment<3>(dof);
  if ((at - position).norm() > 1e-9 * std::max(1.0, position.norm()))
    throw InputError(fmt::format("the cable {} [{}, {}, {}] is not at knot '{}' [{}, {}, {}]",
                                 which, position.x(), position.y(), position.z(), knot, at.x(),
                                 at.y(), at.z()));
  return dof;
}

namespace {

// The properties of a beam's centre line (model.hpp, CableElement): EA, the smaller EI, ρA; the
// drawing radius of `drawn`. A beam has no rope law, and its Kelvin–Voigt damping is the beam
// material's (the centre line is undamped: the beam kernel damps): both refused in `drawn`
// unless they agree.
CableProperties MakeBeamCentreLineProperties(const CableSpec& spec) {
  const CableProperties& drawn = spec.properties;
  if (drawn.tension_only)
    throw InputError(fmt::format(
        "cable '{}' is made of ancf_beam elements, which have no rope law (tension_only)",
        spec.name));
  if (drawn.axial_damping_time != spec.beam->material.axial_damping_time ||
      drawn.bending_damping_time != spec.beam->material.bending_damping_time)
    throw InputError(fmt::format(
        "cable '{}' is made of ancf_beam elements: give its damping times in the beam's material",
        spec.name));
  const BeamElementParameters p =
      MakeBeamElementParameters(spec.beam->material, spec.beam->section, 1.0);
  CableProperties properties;
  properties.axial_stiffness = p.axial_stiffness;
  properties.bending_stiffness = std::min(p.bending_stiffness_y, p.bending_stiffness_z);
  properties.mass_per_length = p.mass_per_length;
  properties.radius = drawn.radius;
  return properties;
}

}  // namespace

CableNode ModelBuilder::ContinuedNode(const CableSpec& spec, const Vector3d& slope,
                                      const BeamSectionFrame* frame) const {
  if (!spec.start_knot.empty())
    throw InputError(fmt::format(
        "cable '{}' cannot both continue cable '{}' and start at knot '{}'", spec.name,
        spec.start_cable, spec.start_knot));
  const Cable& earlier = model_.cables_[model_.FindCable(spec.start_cable)];
  const CableNode node = model_.nodes_[earlier.first_node + earlier.num_elements];
  const VectorXd& q0 = model_.initial_positions_;
  const Vector3d end = q0.segment<3>(node.position_dof);
  const Vector3d end_slope = q0.segment<3>(node.slope_dof);
  const double scale = std::max(1.0, end.norm());
  if ((end - spec.start).norm() > 1e-9 * scale || (end_slope - slope).norm() > 1e-9 * slope.norm())
    throw InputError(fmt::format(
        "cable '{}' continues cable '{}', so it must start at its end [{}, {}, {}] in the same "
        "direction and with the same stretch",
        spec.name, spec.start_cable, end.x(), end.y(), end.z()));
  if (frame != nullptr && node.section_dof >= 0 &&
      ((q0.segment<3>(node.section_dof) - frame->d2).norm() > 1e-9 ||
       (q0.segment<3>(node.section_dof + 3) - frame->d3).norm() > 1e-9))
    throw InputError(fmt::format(
        "beam '{}' continues beam '{}' but its orientation gives another section frame",
        spec.name, spec.start_cable));
  return node;
}

Index ModelBuilder::AddCable(const CableSpec& spec) {
  CheckNameIsFree(spec.name);
  RequireFinite(spec.start, "cable start");
  RequireFinite(spec.end, "cable end");
  if (spec.num_elements < 1)
    throw InputError(fmt::format("a cable needs at least 1 element (got {})", spec.num_elements));
  const double distance = (spec.end - spec.start).norm();
  if (!(distance > 0.0))
    throw InputError(fmt::format("cable '{}' has zero length (start equals end)", spec.name));
  RequireNonNegative(spec.natural_length, "natural length");
  const double length = spec.natural_length > 0.0 ? spec.natural_length : distance;
  const CableProperties properties =
      spec.beam ? MakeBeamCentreLineProperties(spec) : spec.properties;
  ValidateProperties(properties);
  RequireBreakingForce(spec.breaking_force, "breaking force of a cable");
  if (std::isfinite(spec.breaking_force) && !(spec.start_knot.empty() && spec.end_knot.empty()))
    throw InputError(fmt::format(
        "cable '{}' can fail but shares a knot's position (an ideal knot), so it could never come "
        "off: use compliant knots (links) for threads that break",
        spec.name));
  // The reference directors of a beam: d₂ from the orientation by Gram–Schmidt, d₃ = t × d₂.
  std::optional<BeamSectionFrame> frame;
  if (spec.beam) {
    RequireFinite(spec.beam->orientation, "beam orientation");
    frame = MakeBeamSectionFrame(spec.end - spec.start, spec.beam->orientation);
  }
  // The slope r' = (end − start)/L is the stretch of the straight cable against its natural
  // length L: a unit tangent when stress-free.
  const Vector3d slope = (spec.end - spec.start) / length;
  std::optional<CableNode> continued;
  if (!spec.start_cable.empty())
    continued = ContinuedNode(spec, slope, frame ? &*frame : nullptr);

  Cable cable;
  cable.name = spec.name;
  cable.first_node = model_.num_nodes();
  cable.first_element = static_cast<Index>(model_.elements_.size());
  cable.num_elements = spec.num_elements;
  cable.length = length;
  cable.properties = properties;
  cable.breaking_force = spec.breaking_force;
  cable.element = spec.beam ? ElementKind::kBeam : ElementKind::kCable;
  const Index cable_index = static_cast<Index>(model_.cables_.size());
  model_.cables_.push_back(cable);
  model_.names_.emplace(cable.name, std::pair{Model::NamedKind::kCable, cable_index});

  for (Index i = 0; i <= spec.num_elements; ++i) {
    const double s = static_cast<double>(i) / spec.num_elements;
    const Vector3d r = spec.start + s * (spec.end - spec.start);
    CableNode node;
    if (i == 0 && continued) {
      node = *continued;
    } else {
      if (i == 0)
        node.position_dof = EndPositionDof(spec.start_knot, r, "start");
      else if (i == spec.num_elements)
        node.position_dof = EndPositionDof(spec.end_knot, r, "end");
      else
        node.position_dof = AddCoordinates(r);
      node.slope_dof = AddCoordinates(slope);
    }
    if (!frame) node.section_dof = -1;  // a cable continuing a beam ignores r_y, r_z
    if (frame && node.section_dof < 0) {
      VectorXd section(6);
      section << frame->d2, frame->d3;
      node.section_dof = AddCoordinates(section);
    }
    model_.nodes_.push_back(node);
  }

  const CableProperties& p = properties;
  for (Index i = 0; i < spec.num_elements; ++i) {
    CableElement element;
    element.cable = cable_index;
    const CableNode& a = model_.nodes_[cable.first_node + i];
    const CableNode& b = model_.nodes_[cable.first_node + i + 1];
    for (int k = 0; k < 3; ++k) {
      element.dofs[k] = a.position_dof + k;
      element.dofs[3 + k] = a.slope_dof + k;
      element.dofs[6 + k] = b.position_dof + k;
      element.dofs[9 + k] = b.slope_dof + k;
    }
    CableElementParameters& ep = element.parameters;
    ep.length = length / spec.num_elements;
    ep.axial_stiffness = p.axial_stiffness;
    ep.bending_stiffness = p.bending_stiffness;
    ep.mass_per_length = p.mass_per_length;
    ep.axial_damping_time = p.axial_damping_time;
    ep.bending_damping_time = p.bending_damping_time;
    ep.tension_only = p.tension_only;
    ep.rope_smoothing_strain = p.rope_smoothing_strain;
    ep.bending_model = p.bending_model;
    ep.axial_gauss_points = p.axial_gauss_points;
    ep.bending_gauss_points = p.bending_gauss_points;
    model_.elements_.push_back(element);
  }
  if (spec.beam) AddBeamElements(spec, cable_index);
  return cable_index;
}

void ModelBuilder::AddBeamElements(const CableSpec& spec, Index cable_index) {
  const Cable& cable = model_.cables_[cable_index];
  const BeamElementParameters parameters = MakeBeamElementParameters(
      spec.beam->material, spec.beam->section, cable.length / cable.num_elements);
  for (Index i = 0; i < cable.num_elements; ++i) {
    BeamElement beam;
    beam.element = cable.first_element + i;
    beam.parameters = parameters;
    for (int n = 0; n < 2; ++n) {
      const CableNode& node = model_.nodes_[cable.first_node + i + n];
      for (int k = 0; k < 3; ++k) {
        const int first = kBeamNodeDofs * n + k;
        beam.dofs[first] = node.position_dof + k;
        beam.dofs[first + 3] = node.slope_dof + k;
        beam.dofs[first + 6] = node.section_dof + k;
        beam.dofs[first + 9] = node.section_dof + 3 + k;
      }
    }
    model_.elements_[beam.element].beam = static_cast<Index>(model_.beam_elements_.size());
    model_.beam_elements_.push_back(beam);
  }
}

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

void ModelBuilder::AddRotatingClamp(const CablePointRef& at, const Vector3d& axis,
                                    const Vector3d& center, const AngleProfile& angle) {
  RequireFinite(axis, "hub axis");
  RequireFinite(center, "hub centre");
  if (!(axis.norm() > 0.0)) throw InputError("a hub's axis must be a non-zero vector");
  if (!std::isfinite(angle.rate)) throw InputError("a hub's rate must be finite");
  if (angle.kind == AngleProfile::Kind::kSpinUp) RequirePositive(angle.ramp_time, "spin-up time");
  AddClamp(at);
  const Index position_dof = model_.nodes_[LocateNode(at)].position_dof;
  for (const Index dof : ClampedBlocks(LocateNode(at))) {
    PrescribedBlock block;
    block.kind = PrescribedBlock::Kind::kRotation;
    block.dof = dof;
    block.initial = model_.initial_positions_.segment<3>(dof);
    block.axis = axis.normalized();
    block.center = center;
    block.is_direction = dof != position_dof;
    block.angle = angle;
    model_.prescribed_.push_back(block);
  }
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

Index ModelBuilder::LocateNode(const CablePointRef& at) const {
  return model_.LocateCableNode(model_.FindCable(at.cable), at.s);
}

void ModelBuilder::FixCoordinates(const CablePointRef& at, const CoordinateMask& mask) {
  const CableNode& node = model_.nodes_[LocateNode(at)];
  for (int k = 0; k < 3; ++k) {
    if (mask[k]) model_.fixed_[node.position_dof + k] = true;
    if (mask[3 + k]) model_.fixed_[node.slope_dof + k] = true;
  }
}

std::vector<Index> ModelBuilder::ClampedBlocks(Index node_index) const {
  const CableNode& node = model_.nodes_[node_index];
  if (node.section_dof < 0) return {node.position_dof, node.slope_dof};
  std::vector<Index> blocks = {node.position_dof, node.section_dof, node.section_dof + 3};
  const bool cable_uses_slope =
      std::any_of(model_.elements_.begin(), model_.elements_.end(), [&](const CableElement& e) {
        return e.beam < 0 && (e.dofs[3] == node.slope_dof || e.dofs[9] == node.slope_dof);
      });
  if (cable_uses_slope) blocks.push_back(node.slope_dof);
  return blocks;
}

void ModelBuilder::AddClamp(const CablePointRef& at) {
  for (const Index block : ClampedBlocks(LocateNode(at)))
    for (int k = 0; k < 3; ++k) model_.fixed_[block + k] = true;
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
    const CableNode& node = model_.nodes_[cable.first_node + i];
    const Vector3d r = model_.initial_positions_.segment<3>(node.position_dof);
    const Vector3d slope = model_.initial_positions_.segment<3>(node.slope_dof);
    // Rigid motion: ṙ = v + ω × (r − c), ṙ' = ω × r'.
    model_.initial_velocities_.segment<3>(node.position_dof) =
        velocity + angular_velocity.cross(r - center);
    model_.initial_velocities_.segment<3>(node.slope_dof) = angular_velocity.cross(slope);
    if (node.section_dof >= 0)
      for (const Index dof : {node.section_dof, node.section_dof + 3})
        model_.initial_velocities_.segment<3>(dof) =
            angular_velocity.cross(Vector3d(model_.initial_positions_.segment<3>(dof)));
  }
}

void ModelBuilder::AddNetDescription(const Net& net) {
  for (const Net& other : model_.nets_)
    if (other.name == net.name) throw InputError(fmt::format("two nets are named '{}'", net.name));
  model_.nets_.push_back(net);
}

Model ModelBuilder::Build() const {
  if (model_.cables_.empty() && model_.point_masses_.empty() && model_.rigid_bodies_.empty())
    throw InputError("the model has no cable, no point mass and no rigid body");
  if (model_.orbital_frame_ && !model_.rigid_bodies_.empty())
    throw InputError("rigid bodies are not available in an orbital (Hill) frame yet");
  if (model_.damping_.modal.num_modes > 0 && model_.has_free_bodies())
    throw InputError(
        "modal damping needs the modes of the model, which free rigid bodies do not have; use "
        "Rayleigh damping or make the bodies fixed");
  if (!model_.beam_elements_.empty() && model_.orbital_frame_)
    throw InputError("ancf_beam cables are not available in an orbital (Hill) frame yet");
  Model model = model_;
  // A fixed coordinate does not move, unless it belongs to a moving point mass.
  for (Index i = 0; i < model.num_dofs(); ++i)
    if (model.fixed_[i]) model.initial_velocities_[i] = 0.0;
  ApplyPrescribedMotion(model.prescribed_, 0.0, nullptr, &model.initial_velocities_, nullptr);
  return model;
}

}  // namespace ancfnet
