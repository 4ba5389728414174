#pragma once
/// @file An isotropic linear spring-damper between a point p (a cable material point or a point
/// mass) and a point s_B of a rigid body, y = x + R s_B (docs/theory.md, "Body attachments"):
///   d = p − y,   u = ṗ − ẏ,   ẏ = ẋ + R (ω × s_B),   f = −k d − c u   (on the point),
/// and −f on the body at y. With the internal forces on the left of M q̈ + Q_int = Q_ext, the
/// generalised forces on (p, x, ψ) are
///   Q_p = −f,   Q_x = f,   Q_ψ = s_B × (Rᵀ f),
/// (Q_x, Q_ψ) = −Gᵀ(−f) with G of model/rigid_body_kinematics.hpp. The Jacobians use
/// δR = R δψ̃ (the tangent operator T(ψ) taken as I, exact at ψ = 0):
///   ∂f/∂p = −k I, ∂f/∂x = k I, ∂f/∂ψ = −k R s̃ − c R (ω × s)~,
///   ∂f/∂ṗ = −c I, ∂f/∂ẋ = c I, ∂f/∂ω = −c R s̃,
///   ∂Q_ψ/∂· = s̃ Rᵀ ∂f/∂· (+ s̃ (Rᵀ f)~ for ψ).
/// Energy ½ k |d|².

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

/// The two ends of an attachment and its law.
struct BodyAttachmentInput {
  Vector3d p = Vector3d::Zero();      ///< point position (m, world)
  Vector3d p_dot = Vector3d::Zero();  ///< its velocity (m/s)
  BodyPose pose;
  BodyVelocity velocity;
  Vector3d s_B = Vector3d::Zero();  ///< body point (m, body frame)
  double stiffness = 0.0;           ///< k (N/m)
  double damping = 0.0;             ///< c (N s/m)
};

struct BodyAttachmentResult {
  Vector3d force_on_point = Vector3d::Zero();  ///< f (N)
  Vector3d viscous_force = Vector3d::Zero();   ///< its damping part −c u (N)
  /// (Q_p, Q_x, Q_ψ): the internal generalised forces on the point, body position, rotation.
  Vector9d generalized = Vector9d::Zero();
  /// Its damping part (for the dissipation account).
  Vector9d generalized_viscous = Vector9d::Zero();
  Matrix9d stiffness = Matrix9d::Zero();  ///< ∂Q/∂(p, x, ψ)
  Matrix9d damping = Matrix9d::Zero();    ///< ∂Q/∂(ṗ, ẋ, ω)
  double energy = 0.0;                    ///< ½ k |d|² (J)
};

/// Force, generalised forces, Jacobians (when `jacobians`) and energy of an attachment.
BodyAttachmentResult CalcBodyAttachment(const BodyAttachmentInput& in, bool jacobians = true);

}  // namespace ancfnet
