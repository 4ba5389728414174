#pragma once
/// @file Assembly of the rigid bodies' terms: their constant mass blocks (m I₃ on x, J_B on ψ),
/// the gyroscopic term ω × J_B ω of free bodies (forces/gyroscopic_force.hpp) and the body
/// attachments (forces/body_attachment.hpp), evaluated with the reference orientations in
/// ws.body_rotation.

#include "ancfnet/forces/body_attachment.hpp"
#include "ancfnet/forces/forces.hpp"

namespace ancfnet {

/// Adds the gyroscopic terms and the attachment forces to ws.internal_force (and the attachments'
/// damping parts to ws.viscous_force).
void AddBodyForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws);

/// Adds c_C ∂/∂q̇ + c_K ∂/∂q of the same terms to `matrix`.
void AddBodyJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                      const IterationWeights& weights, const Workspace& ws, SystemMatrix* matrix);

/// Adds scale · (m I₃, J_B) on the diagonal blocks of every body.
void AddBodyMassMatrix(const Model& model, double scale, SystemMatrix* matrix);

/// One attachment at (q, v) with the reference orientations `rotation` (a State's or Workspace's
/// body_rotation).
BodyAttachmentResult CalcAttachmentState(const Model& model, const BodyAttachment& attachment,
                                         const VectorXd& q, const VectorXd& v,
                                         const std::vector<Matrix3d>& rotation,
                                         bool jacobians = false);

/// Energy stored in the attachments, Σ ½ k |d|² (J).
double CalcAttachmentEnergy(const Model& model, const Workspace& ws, const VectorXd& q);

/// Kinetic energy of the bodies Σ ½ m |ẋ|² + ½ ωᵀ J_B ω (J).
double CalcBodyKineticEnergy(const Model& model, const VectorXd& v);

}  // namespace ancfnet
