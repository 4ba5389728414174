#pragma once
/// @file Rigid bodies (a tumbling target, a chaser) and their attachments to cable points and
/// point masses. A body has six coordinates in the global vectors: its position x_WB (world, m)
/// and a rotation-vector increment ψ (rad) relative to a reference orientation R_ref kept per body
/// in the State, R_WB = R_ref exp(ψ̃). Its velocities are (ẋ_WB world, ω_B body frame) and its
/// accelerations (ẍ_WB, ω̇_B): the Lie-group generalised-α of Brüls, Cardona & Arnold (2012)
/// written additively (docs/theory.md, "Rigid bodies").

#include <string>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// How a body moves.
enum class BodyMotion {
  kFree,        ///< integrated: m ẍ = F, J_B ω̇ + ω × J_B ω = M_B
  kFixed,       ///< at rest at its initial pose
  kPrescribed,  ///< constant linear velocity (world) and constant angular velocity
};

/// A body as given to ModelBuilder::AddRigidBody.
struct RigidBodySpec {
  std::string name;
  double mass = 0.0;                             ///< m (kg), > 0
  Matrix3d inertia = Matrix3d::Identity();       ///< J_B about the centre of mass (kg m²)
  Vector3d position = Vector3d::Zero();          ///< x_WB of the centre of mass (m)
  Matrix3d orientation = Matrix3d::Identity();   ///< R_WB (a rotation matrix)
  Vector3d velocity = Vector3d::Zero();          ///< ẋ_WB (m/s, world)
  Vector3d angular_velocity = Vector3d::Zero();  ///< ω (rad/s), in the frame below
  bool angular_velocity_in_world = false;        ///< ω given in world axes (ω_B = R_WBᵀ ω_W)
  BodyMotion motion = BodyMotion::kFree;
};

/// A body of the Model. Its coordinates: x at dof … dof + 2, ψ at dof + 3 … dof + 5.
struct RigidBody {
  std::string name;
  double mass = 0.0;
  Matrix3d inertia = Matrix3d::Identity();              ///< J_B (kg m²), SPD
  Matrix3d initial_orientation = Matrix3d::Identity();  ///< R_WB at t = 0
  BodyMotion motion = BodyMotion::kFree;
  Index dof = 0;
  Index position_dof() const { return dof; }
  Index rotation_dof() const { return dof + 3; }
};

/// Throws InputError unless J is symmetric positive definite with principal moments satisfying
/// the triangle inequality J₁ + J₂ ≥ J₃ (every permutation), as a mass distribution must.
void ValidateInertia(const Matrix3d& inertia, const std::string& body);

/// Throws InputError unless R is a rotation matrix (RᵀR = I, det R = +1, to 1e-6).
void ValidateRotation(const Matrix3d& rotation, const std::string& what);

}  // namespace ancfnet
