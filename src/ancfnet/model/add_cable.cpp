// ModelBuilder (model/model_builder.hpp): cables and beams, their nodes and elements, how a cable
// starts at a knot or continues another, and their initial velocities.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

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

CableNode ModelBuilder::ContinuedNode(const CableSpec& spec, const Vector3d& slope,
                                      const BeamSectionFrame* frame) const {
  if (!spec.start_knot.empty())
    throw InputError(
        fmt::format("cable '{}' cannot both continue cable '{}' and start at knot '{}'", spec.name,
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
    throw InputError(
        fmt::format("beam '{}' continues beam '{}' but its orientation gives another section frame",
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
  if (std::isfinite(spec.breaking_force) && !spec.start_knot.empty() && !spec.end_knot.empty())
    throw InputError(fmt::format(
        "cable '{}' can fail but shares the positions of knots at both ends (ideal knots), so it "
        "could never come off: use compliant knots (links) for threads that break",
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
  if (!spec.start_cable.empty()) continued = ContinuedNode(spec, slope, frame ? &*frame : nullptr);

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

}  // namespace ancfnet
