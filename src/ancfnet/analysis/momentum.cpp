#include "ancfnet/analysis/momentum.hpp"

#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

Vector3d CalcLinearMomentum(const Model& model, const Workspace& ws, const VectorXd& v) {
  Vector3d p = Vector3d::Zero();
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    // The position rows (blocks 0 and 2) of M_e ė.
    const Vector12d force = ws.element_mass[e] * model.Gather(elements[e], v);
    p += force.segment<3>(0) + force.segment<3>(6);
  }
  for (const PointMass& point : model.point_masses()) p += point.mass * v.segment<3>(point.dof);
  for (const RigidBody& body : model.rigid_bodies())
    p += body.mass * v.segment<3>(body.position_dof());
  return p;
}

Vector3d CalcAngularMomentum(const Model& model, const Workspace& ws, const VectorXd& q,
                             const VectorXd& v) {
  Vector3d angular = Vector3d::Zero();
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Vector12d x = model.Gather(elements[e], q);
    const Vector12d x_dot = model.Gather(elements[e], v);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        angular += ws.element_mass[e](3 * i, 3 * j) *
                   Vector3d(x.segment<3>(3 * i)).cross(Vector3d(x_dot.segment<3>(3 * j)));
  }
  // The spin of beam sections: ∫ (ρI_z d₂ × ḋ₂ + ρI_y d₃ × ḋ₃) dx over the eight blocks.
  const auto& beams = model.beam_elements();
  for (std::size_t b = 0; b < beams.size(); ++b) {
    const Vector24d x = model.Gather(beams[b], q);
    const Vector24d x_dot = model.Gather(beams[b], v);
    for (int i = 0; i < kBeamElementBlocks; ++i)
      for (int j = 0; j < kBeamElementBlocks; ++j)
        if (ws.beam_rotary_mass[b](3 * i, 3 * j) != 0.0)
          angular += ws.beam_rotary_mass[b](3 * i, 3 * j) *
                     Vector3d(x.segment<3>(3 * i)).cross(Vector3d(x_dot.segment<3>(3 * j)));
  }
  for (const PointMass& point : model.point_masses())
    angular += point.mass * Vector3d(q.segment<3>(point.dof)).cross(Vector3d(v.segment<3>(point.dof)));
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyPose pose = CalcBodyPose(bodies[b], q, ws.body_rotation[b]);
    const Vector3d w_B = v.segment<3>(bodies[b].rotation_dof());
    angular += bodies[b].mass * pose.p_WB.cross(Vector3d(v.segment<3>(bodies[b].position_dof()))) +
               pose.R_WB * (bodies[b].inertia * w_B);
  }
  return angular;
}

}  // namespace ancfnet
