#pragma once
/// @file Signed distance of a point to a box (an oriented rigid target), with the outward normal
/// and the Hessian; the gap of a sphere (knot, inspection sphere, capsule end) of radius r is
/// distance − r.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Signed distance of a point to a box and its derivatives with respect to the point.
struct PointBoxDistance {
  double distance = 0.0;   ///< φ (m): > 0 outside, < 0 inside, 0 on the surface
  Vector3d closest_point;  ///< nearest point of the box surface (m)
  Vector3d normal;         ///< outward unit normal n = ∂φ/∂p, p = x + φ n
  Matrix3d hessian;  ///< ∂²φ/∂p² (1/m): 0 inside and on faces, ≠ 0 near edges and corners
  bool inside = false;  ///< φ ≤ 0
};

/// Signed distance of the point p_W to the box of centre c_W, half extents h > 0 along its own
/// axes and orientation R_WB (columns: the box axes in world) (m). In the box frame
/// q = R_WBᵀ (p − c), w = q − clamp(q, −h, h):
///   outside (w ≠ 0): φ = |w|, n = R_WB w/|w|, ∂²φ/∂p² = R_WB (D − n_B n_Bᵀ) R_WBᵀ/φ, with D
///   the diagonal 0/1 mask of the clamped axes (the distance to a face, an edge or a corner);
///   inside: φ = −min_k (h_k − |q_k|), the nearest face k, n = ±R_WB e_k (+ for q_k = 0), Hessian
///   0.
/// φ is C¹ across the outside regions; inside it has kinks where two faces are equally near
/// (the lowest k wins). Ericson (2005), §5.1.4.
PointBoxDistance CalcPointBoxDistance(const Vector3d& p, const Vector3d& center,
                                      const Vector3d& half_extents, const Matrix3d& R_WB);

}  // namespace ancfnet
