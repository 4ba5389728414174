#include "ancfnet/state/workspace.hpp"

#include "ancfnet/model/model.hpp"

namespace ancfnet {

Workspace::Workspace(const Model& model)
    : element_mass(model.elements().size()),
      gravity_force(VectorXd::Zero(model.num_dofs())),
      distributed_force(VectorXd::Zero(model.num_dofs())),
      element_force(model.elements().size()),
      element_viscous_force(model.elements().size()),
      element_step_start(model.elements().size()),
      element_step_correction(model.elements().size(), Vector12d::Zero()),
      element_step_jacobian(model.elements().size(), Matrix12d::Zero()),
      element_stiffness(model.elements().size()),
      element_damping(model.elements().size()),
      beam_force(model.beam_elements().size()),
      beam_viscous_force(model.beam_elements().size()),
      beam_stiffness(model.beam_elements().size()),
      beam_damping(model.beam_elements().size()),
      link_broken(model.links().size(), 0),
      joint_history(model.clearance_joints().size()),
      internal_force(VectorXd::Zero(model.num_dofs())),
      viscous_force(VectorXd::Zero(model.num_dofs())),
      applied_force(VectorXd::Zero(model.num_dofs())),
      external_force(VectorXd::Zero(model.num_dofs())),
      drive_force(VectorXd::Zero(model.num_dofs())) {
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const CableElementParameters& p = elements[e].parameters;
    element_mass[e] = CalcCableMassMatrix(p);
    const Vector12d fg = CalcCableDistributedForce(p, p.mass_per_length * model.gravity());
    for (int i = 0; i < kCableElementDofs; ++i) gravity_force[elements[e].dofs[i]] += fg[i];
  }
  for (const BeamElement& beam : model.beam_elements()) {
    BeamElementParameters rotary = beam.parameters;
    rotary.mass_per_length = 0.0;
    beam_rotary_mass.push_back(CalcBeamMassMatrix(rotary));
    element_force[beam.element].setZero();
    element_viscous_force[beam.element].setZero();
    element_stiffness[beam.element].setZero();
    element_damping[beam.element].setZero();
  }
  for (const PointMass& point : model.point_masses())
    gravity_force.segment<3>(point.dof) += point.mass * model.gravity();
  for (const RigidBody& body : model.rigid_bodies()) {
    body_rotation.push_back(body.initial_orientation);
    if (body.motion == BodyMotion::kFree)
      gravity_force.segment<3>(body.position_dof()) += body.mass * model.gravity();
  }
  for (const DistributedLoad& load : model.distributed_loads()) {
    const Cable& cable = model.cables()[load.cable];
    for (Index e = cable.first_element; e < cable.first_element + cable.num_elements; ++e) {
      const Vector12d f = CalcCableDistributedForce(elements[e].parameters, load.force_per_length);
      for (int i = 0; i < kCableElementDofs; ++i) distributed_force[elements[e].dofs[i]] += f[i];
    }
  }
}

}  // namespace ancfnet
