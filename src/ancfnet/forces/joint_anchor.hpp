#pragma once
/// @file The motion of a joint anchor (model/clearance_joint.hpp) from the global vectors, as a
/// rigid-like frame: its centre c, velocity ċ and angular velocity ω (world), linear in the
/// velocities of its 3-coordinate blocks v_b,
///   ċ = Σ_b A_b v_b,   ω = Σ_b B_b v_b,
/// so that a force f at the centre and a moment m do the virtual work Σ_b δq_bᵀ (A_bᵀ f + B_bᵀ m):
///   ground:      no blocks, ċ = 0, ω = 0;
///   rigid body:  blocks (x, ψ), c = x + R s_B, A = (I, −R s̃), B = (0, R)
///                (model/rigid_body_kinematics.hpp; δR = R δψ̃);
///   point mass:  one block, A = I, B = 0;
///   cable point: blocks (r_A, r'_A, r_B, r'_B), A_b = w_b I, and with the slope a = r' the
///                turning ω = a × ȧ/|a|², B_b = w'_b ã/|a|², so that B_bᵀ m = w'_b (m × a)/|a|²,
///                the slope force of a point moment (forces/slope_moment.hpp).
/// With the derivatives the Jacobians need: C_b = ∂ċ/∂q_b, D_b = ∂ω/∂q_b, and the geometric
/// stiffness ∂(Σ A_bᵀ f + B_bᵀ m)/∂q at fixed (f, m). docs/theory.md, "Clearance joints".

#include <array>
#include <vector>

#include "ancfnet/model/clearance_joint.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// An anchor's motion at (q, v) and its maps; blocks beyond num_blocks are unused.
struct AnchorMotion {
  int num_blocks = 0;
  std::array<Index, 4> dof{};                    ///< first coordinate of each block
  Vector3d center = Vector3d::Zero();            ///< c (m)
  Vector3d velocity = Vector3d::Zero();          ///< ċ (m/s)
  Vector3d angular_velocity = Vector3d::Zero();  ///< ω (rad/s, world)
  std::array<Matrix3d, 4> a{};                   ///< A_b = ∂ċ/∂v_b = ∂c/∂q_b
  std::array<Matrix3d, 4> b{};                   ///< B_b = ∂ω/∂v_b
  std::array<Matrix3d, 4> c{};                   ///< C_b = ∂ċ/∂q_b
  std::array<Matrix3d, 4> d{};                   ///< D_b = ∂ω/∂q_b
  // For the geometric stiffness: the body's R and s_B, or the cable's slope a.
  Matrix3d rotation = Matrix3d::Identity();
  Vector3d body_point = Vector3d::Zero();
  Vector3d slope = Vector3d::Zero();
  Vector3d slope_rate = Vector3d::Zero();  ///< ȧ of a cable point's slope
  JointAnchor::Kind kind = JointAnchor::Kind::kGround;
  bool has_slope = false;
  std::array<double, 4> slope_weight{};

  /// Generalised force of block k of a force f at the centre and a moment m: A_kᵀ f + B_kᵀ m.
  Vector3d GeneralizedForce(int k, const Vector3d& f, const Vector3d& m) const {
    return a[k].transpose() * f + b[k].transpose() * m;
  }
  /// ∂(A_kᵀ f + B_kᵀ m)/∂q_l at fixed (f, m): s̃ (Rᵀ f)~ + (Rᵀ m)~ on a body's (ψ, ψ) block,
  /// w'_k w'_l ∂((m × a)/|a|²)/∂a on a cable point's, zero elsewhere.
  Matrix3d GeometricStiffness(int k, int l, const Vector3d& f, const Vector3d& m) const;
};

/// The centre c of `anchor` at q (m, world), with the bodies' reference rotations `rotation`.
Vector3d CalcAnchorCenter(const Model& model, const JointAnchor& anchor, const VectorXd& q,
                          const std::vector<Matrix3d>& rotation);

/// The motion of `anchor` at (q, v); a body's pose uses its reference rotation in `rotation`
/// (State::body_rotation or Workspace::body_rotation).
AnchorMotion CalcAnchorMotion(const Model& model, const JointAnchor& anchor, const VectorXd& q,
                              const VectorXd& v, const std::vector<Matrix3d>& rotation);

}  // namespace ancfnet
