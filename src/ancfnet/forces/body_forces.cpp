#include "ancfnet/forces/body_forces.hpp"

#include "ancfnet/forces/gyroscopic_force.hpp"

namespace ancfnet {
namespace {

// The attachment's generalised-force block r (0: point, 1: x, 2: ψ) of group block b, and the
// weight of that block (w_b of the point's blocks, 1 for the body's).
struct GroupBlock {
  int row = 0;
  double weight = 1.0;
};

GroupBlock AttachmentBlock(const BodyAttachment& attachment, int b) {
  const int n = attachment.point.num_blocks;
  if (b < n) return {0, attachment.point.weight[b]};
  return {1 + (b - n), 1.0};
}

Index AttachmentBlockDof(const Model& model, const BodyAttachment& attachment, int b) {
  const int n = attachment.point.num_blocks;
  const RigidBody& body = model.rigid_bodies()[attachment.body];
  if (b < n) return attachment.point.dof[b];
  return b == n ? body.position_dof() : body.rotation_dof();
}

}  // namespace

BodyAttachmentResult CalcAttachmentState(const Model& model, const BodyAttachment& attachment,
                                         const VectorXd& q, const VectorXd& v,
                                         const std::vector<Matrix3d>& rotation, bool jacobians) {
  const RigidBody& body = model.rigid_bodies()[attachment.body];
  return CalcBodyAttachment({.p = Model::Locate(attachment.point, q),
                             .p_dot = Model::Locate(attachment.point, v),
                             .pose = CalcBodyPose(body, q, rotation[attachment.body]),
                             .velocity = CalcBodyVelocity(body, v),
                             .s_B = attachment.body_point,
                             .stiffness = attachment.stiffness,
                             .damping = attachment.damping},
                            jacobians);
}

void AddBodyForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws) {
  for (const RigidBody& body : model.rigid_bodies())
    if (body.motion == BodyMotion::kFree)
      ws.internal_force.segment<3>(body.rotation_dof()) +=
          CalcGyroscopicForce(body.inertia, v.segment<3>(body.rotation_dof()));
  for (const BodyAttachment& attachment : model.body_attachments()) {
    const BodyAttachmentResult r = CalcAttachmentState(model, attachment, q, v, ws.body_rotation);
    const int blocks = attachment.point.num_blocks + 2;
    for (int b = 0; b < blocks; ++b) {
      const auto [row, weight] = AttachmentBlock(attachment, b);
      const Index dof = AttachmentBlockDof(model, attachment, b);
      ws.internal_force.segment<3>(dof) += weight * r.generalized.segment<3>(3 * row);
      ws.viscous_force.segment<3>(dof) += weight * r.generalized_viscous.segment<3>(3 * row);
    }
  }
}

void AddBodyJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                      const IterationWeights& weights, const Workspace& ws, SystemMatrix* matrix) {
  const auto& bodies = model.rigid_bodies();
  if (weights.damping != 0.0)
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (bodies[b].motion == BodyMotion::kFree)
        matrix->AddBodyBlock(
            static_cast<Index>(b), 1, 1,
            CalcGyroscopicJacobian(bodies[b].inertia, v.segment<3>(bodies[b].rotation_dof())),
            weights.damping);
  const auto& attachments = model.body_attachments();
  for (std::size_t a = 0; a < attachments.size(); ++a) {
    const BodyAttachmentResult r =
        CalcAttachmentState(model, attachments[a], q, v, ws.body_rotation, /*jacobians=*/true);
    const Matrix9d jacobian = weights.stiffness * r.stiffness + weights.damping * r.damping;
    const int blocks = attachments[a].point.num_blocks + 2;
    for (int i = 0; i < blocks; ++i)
      for (int j = 0; j < blocks; ++j) {
        const GroupBlock bi = AttachmentBlock(attachments[a], i);
        const GroupBlock bj = AttachmentBlock(attachments[a], j);
        matrix->AddAttachmentBlock(static_cast<Index>(a), i, j,
                                   jacobian.block<3, 3>(3 * bi.row, 3 * bj.row),
                                   bi.weight * bj.weight);
      }
  }
}

void AddBodyMassMatrix(const Model& model, double scale, SystemMatrix* matrix) {
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    matrix->AddBodyBlock(static_cast<Index>(b), 0, 0, Matrix3d::Identity(), scale * bodies[b].mass);
    matrix->AddBodyBlock(static_cast<Index>(b), 1, 1, bodies[b].inertia, scale);
  }
}

double CalcAttachmentEnergy(const Model& model, const Workspace& ws, const VectorXd& q) {
  double energy = 0.0;
  for (const BodyAttachment& attachment : model.body_attachments()) {
    const RigidBody& body = model.rigid_bodies()[attachment.body];
    const BodyPose pose = CalcBodyPose(body, q, ws.body_rotation[attachment.body]);
    energy += 0.5 * attachment.stiffness *
              (Model::Locate(attachment.point, q) - pose.PointInWorld(attachment.body_point))
                  .squaredNorm();
  }
  return energy;
}

double CalcBodyKineticEnergy(const Model& model, const VectorXd& v) {
  double energy = 0.0;
  for (const RigidBody& body : model.rigid_bodies()) {
    const Vector3d w = v.segment<3>(body.rotation_dof());
    energy += 0.5 * body.mass * v.segment<3>(body.position_dof()).squaredNorm() +
              0.5 * w.dot(body.inertia * w);
  }
  return energy;
}

}  // namespace ancfnet
