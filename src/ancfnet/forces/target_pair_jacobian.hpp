#pragma once
/// @file The complete Jacobian of the generalised forces of one probe–target pair: the probe's
/// Q = −W(t*)ᵀ f and, for a target carried by a rigid body, the body's Q = Gᵀ f (a force in
/// world axes and a moment in body axes), with respect to the probe's coordinates and the body's
/// pose and velocities. It holds every term: the normal and the tangent plane turning with the
/// contact point, the closest point and t* moving with the probe and with the body, the slip
/// velocity's dependence on the pose (through the surface point and ω), the bristle turning with
/// the body, and the variation of G (docs/theory.md, "Complete contact Jacobians").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/contact_pair_force.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

using Matrix18d = Eigen::Matrix<double, 18, 18>;

/// Where a probe touches a target, in world coordinates: what the Jacobian needs beyond the
/// pair force.
struct TargetPairGeometry {
  int num_blocks = 1;  ///< the probe's 3-coordinate blocks: 4 (cable element), 1 (point mass)
  /// w_k = (1 − t*) S_k(ξ₀) + t* S_k(ξ₁): the probe point is x = Σ w_k e_k (a point mass: w₀ = 1).
  Vector4d weights = Vector4d::UnitX();
  Vector4d weight_rates = Vector4d::Zero();  ///< d_k = S_k(ξ₁) − S_k(ξ₀) = ∂w_k/∂t*
  /// t* is an interior minimum of φ along the axis with φ'' = Δᵀ H Δ > 0: it moves with the
  /// coordinates. Otherwise (a sphere, an end of the axis) it is fixed.
  bool moving_point = false;
  Vector3d axis = Vector3d::Zero();       ///< Δ = x₁ − x₀ (m)
  Vector3d axis_rate = Vector3d::Zero();  ///< Δ̇ (m/s)
  Vector3d point = Vector3d::Zero();      ///< x = c(t*) (m)
  double distance = 0.0;                  ///< φ(x) (m)
  Vector3d normal = Vector3d::UnitZ();    ///< n = ∂φ/∂x
  Matrix3d hessian = Matrix3d::Zero();    ///< H = ∂n/∂x (1/m)
  /// The target's body, when it has one: its pose, ω_W = R_WB ω_B and the bristle deflection
  /// z₀ = R_WB z_B the force was computed with.
  bool on_body = false;
  BodyPose pose;
  Vector3d angular_velocity = Vector3d::Zero();
  Vector3d bristle = Vector3d::Zero();
};

/// c_K ∂Q/∂q + c_C ∂Q/∂q̇ of the pair, rows and columns ordered: the probe's blocks 0 … 3
/// (coordinates 0 … 11; a point mass uses block 0), the body's x (12 … 14) and ψ (15 … 17),
/// δR = R δψ̃ (exact at ψ = 0). With θ = R δψ, d = x − x_WB, a = s − x_WB (s = x − φ n the
/// surface point), P = I − n nᵀ and u = ẋ − ẋ_WB − ω_W × a the slip:
///   δx_rel = W δe + Δ δt* − δx_WB − θ × d,   δφ = nᵀ δx_rel,   δn = H δx_rel + θ × n,
///   δa = (P − φ H) δx_rel + θ × a,   δz₀ = θ × z₀,
///   δu = W δė + Δ̇ δt* − δẋ_WB + a × R δω_B − ω_W × (P − φ H) δx_rel + (ω_W × a) × θ,
///   δt* = −(Δᵀ H (δx_rel)_{t* fixed} + nᵀ D δe + Δᵀ (θ × n))/φ''   (from δ(n·Δ) = 0),
///   δf = (∂f/∂x) δx_rel + (∂f/∂ẋ) δu + (∂f/∂n)(θ × n) + (∂f/∂z₀)(θ × z₀),
///   δQ_e = −Wᵀ δf − Dᵀ f δt*,   δQ_x = δf,   δQ_ψ = (Rᵀ (a × f))~ δψ + Rᵀ (a × δf − f × δa),
/// ∂f/∂x, ∂f/∂ẋ, ∂f/∂n and ∂f/∂z₀ those of CalcContactPairForce (docs/theory.md, "Complete contact
/// Jacobians"). Fixed targets: the body's rows and columns are zero. No allocation.
Matrix18d CalcTargetPairJacobian(const TargetPairGeometry& geometry, const ContactPairForce& force,
                                 double stiffness_weight, double damping_weight);

}  // namespace ancfnet
