#pragma once
/// @file Kinematics of a rigid body from the global vectors: its pose R_WB = R_ref exp(ψ̃) and
/// velocities, and the map G of a world point p fixed on the body,
///   ṗ = ẋ_WB + ω_W × (p − x_WB) = G (ẋ_WB, ω_B),   G = [I₃, −(p − x_WB)~ R_WB],
/// whose transpose turns a world force f at p into the body's generalised force
///   Gᵀ f = (f, R_WBᵀ ((p − x_WB) × f))   (force in world, moment in the body frame),
/// the work-conjugate of (ẋ_WB, ω_B). This is the interface contact with bodies builds on.

#include <vector>

#include "ancfnet/common/skew.hpp"
#include "ancfnet/common/types.hpp"
#include "ancfnet/model/rigid_body.hpp"

namespace ancfnet {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix3x6d = Eigen::Matrix<double, 3, 6>;

/// Rodrigues' formula exp(ψ̃) = I + (sin θ/θ) ψ̃ + ((1 − cos θ)/θ²) ψ̃², θ = |ψ| (series near 0).
Matrix3d ExpRotation(const Vector3d& psi);

/// Pose of a body: position x_WB (m) and orientation R_WB.
struct BodyPose {
  Vector3d p_WB = Vector3d::Zero();
  Matrix3d R_WB = Matrix3d::Identity();
  /// World position of the body point s_B: x_WB + R_WB s_B.
  Vector3d PointInWorld(const Vector3d& s_B) const { return p_WB + R_WB * s_B; }
};

/// Velocities of a body: ẋ_WB (m/s, world) and ω_B (rad/s, body frame).
struct BodyVelocity {
  Vector3d v_WB = Vector3d::Zero();
  Vector3d w_B = Vector3d::Zero();
};

/// Pose from the coordinates q and the body's reference rotation R_ref (State::body_rotation).
BodyPose CalcBodyPose(const RigidBody& body, const VectorXd& q, const Matrix3d& rotation_ref);
/// Velocities from v.
BodyVelocity CalcBodyVelocity(const RigidBody& body, const VectorXd& v);

/// G = [I₃, −(p − x_WB)~ R_WB] of a world point p on the body: ṗ = G (ẋ_WB, ω_B).
Matrix3x6d CalcPointVelocityMap(const BodyPose& pose, const Vector3d& p_W);
/// Gᵀ f = (f, R_WBᵀ ((p − x_WB) × f)): the generalised force of a world force f (N) at p.
Vector6d CalcGeneralizedForce(const BodyPose& pose, const Vector3d& p_W, const Vector3d& f_W);

}  // namespace ancfnet
