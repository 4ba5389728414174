#pragma once
/// @file A free rigid body in the orbital (Hill) frame (forces/orbital_frame.hpp): its centre of
/// mass moves as a point of mass m under the Clohessy–Wiltshire field, K x + G ẋ; its rotation is
/// that of the body relative to the Hill axes, ω_B (body frame), while Euler's equations hold for
/// the inertial rate ω + Ω_B, Ω_B = n R_WBᵀ e_z (the orbit's rate, constant in Hill axes, so
/// dΩ_B/dt = −ω × Ω_B), under the gravity-gradient torque 3n² ê × J ê, ê = R_WBᵀ e_x (Hughes
/// 1986, "Spacecraft attitude dynamics", §8.1). On the left of M q̈ + Q = 0, besides ω × J ω:
///   Q_x = −m (K x + G ẋ),
///   Q_ψ = −J (ω × Ω) + ω × J Ω + Ω × J ω          (workless: ωᵀ(…) = 0)
///         + Ω × J Ω − 3n² ê × J ê                 (= ∂V/∂θ),
/// with the potential V = −½ m xᵀ K x + (3n²/2) êᵀ J ê − ½ Ω_Bᵀ J Ω_B, which is the tidal
/// potential −½ Σ mᵢ rᵢᵀ K rᵢ of the body's mass points (up to a constant): the Jacobi integral
/// ½ m |ẋ|² + ½ ωᵀ J ω + V is conserved (docs/theory.md, "Rigid bodies in an orbital frame").

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

/// The frame's terms on one free body with pose `pose` (x_WB, R_WB), velocities `velocity`
/// (ẋ_WB, ω_B), inertia J_B and mass m, at mean motion n.
struct HillBodyTerms {
  Vector3d force = Vector3d::Zero();   ///< Q_x (N), on the left
  Vector3d moment = Vector3d::Zero();  ///< Q_ψ (N m, body axes), on the left
  /// ∂Q_ψ/∂θ and ∂Q_ψ/∂ω for a body-frame rotation increment δR = R δθ̃ (the body's ψ at ψ = 0);
  /// ∂Q_x/∂x = −m K and ∂Q_x/∂ẋ = −m G (forces/orbital_frame.hpp).
  Matrix3d moment_rotation = Matrix3d::Zero();
  Matrix3d moment_rate = Matrix3d::Zero();
};

HillBodyTerms CalcHillBodyTerms(double mass, const Matrix3d& inertia, const BodyPose& pose,
                                const BodyVelocity& velocity, double mean_motion);

/// V = −½ m xᵀ K x + (3n²/2) êᵀ J ê − ½ Ω_Bᵀ J Ω_B (J).
double CalcHillBodyPotential(double mass, const Matrix3d& inertia, const BodyPose& pose,
                             double mean_motion);

}  // namespace ancfnet
