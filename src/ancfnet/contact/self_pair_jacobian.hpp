#pragma once
/// @file The complete Jacobian of the generalised forces of one self-contact pair of capsules
/// (or spheres): Q_a = −W_a(s*)ᵀ f and Q_b = W_b(t*)ᵀ f, f(x, ẋ) the pair force of the relative
/// position x = x_a(s*) − x_b(t*) of the closest points of the two axes, with the closest-point
/// parameters s*, t* moving with the coordinates (docs/theory.md, "Complete contact Jacobians").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/contact_pair_force.hpp"

namespace ancfnet {

using Matrix24d = Eigen::Matrix<double, 24, 24>;

/// One side of a pair: a primitive's axis x(p) = (1 − p) x₀ + p x₁ and its closest point p*.
struct SelfPairSide {
  int num_blocks = 1;  ///< 3-coordinate blocks: 4 (cable element), 1 (point mass)
  /// w_k = (1 − p*) S_k(ξ₀) + p* S_k(ξ₁): x(p*) = Σ w_k e_k (a point mass: w₀ = 1).
  Vector4d weights = Vector4d::UnitX();
  Vector4d weight_rates = Vector4d::Zero();  ///< d_k = S_k(ξ₁) − S_k(ξ₀) = ∂w_k/∂p
  /// p* lies inside the axis (0 < p* < 1, the two axes not parallel): it moves with the
  /// coordinates. Otherwise (an end, a sphere) it is fixed.
  bool moving_point = false;
  Vector3d axis = Vector3d::Zero();       ///< Δ = x₁ − x₀ (m)
  Vector3d axis_rate = Vector3d::Zero();  ///< Δ̇ (m/s)
};

/// c_K ∂Q/∂q + c_C ∂Q/∂q̇ of the pair, rows and columns ordered a's blocks 0 … 3 (coordinates
/// 0 … 11), then b's (12 … 23); a point mass uses its side's first block. With x = x_a − x_b the
/// separation and δx̂ = W_a δe_a − W_b δe_b at fixed (s*, t*), the stationarity of |x|²,
/// Δ_aᵀ x = 0 (s* inside) and Δ_bᵀ x = 0 (t* inside), gives
///   [Δ_a·Δ_a  −Δ_a·Δ_b; Δ_b·Δ_a  −Δ_b·Δ_b] (δs*, δt*) = −(xᵀ D_a δe_a + Δ_aᵀ δx̂,
///                                                           xᵀ D_b δe_b + Δ_bᵀ δx̂)
/// (the rows and unknowns of a fixed end dropped), then
///   δx = δx̂ + Δ_a δs* − Δ_b δt*,   δẋ = W_a δė_a − W_b δė_b + Δ̇_a δs* − Δ̇_b δt*,
///   δf = (∂f/∂x) δx + (∂f/∂ẋ) δẋ,   δQ_a = −W_aᵀ δf − D_aᵀ f δs*,   δQ_b = W_bᵀ δf + D_bᵀ f δt*.
/// No allocation.
Matrix24d CalcSelfPairJacobian(const SelfPairSide& a, const SelfPairSide& b,
                               const Vector3d& separation, const ContactPairForce& force,
                               double stiffness_weight, double damping_weight);

}  // namespace ancfnet
