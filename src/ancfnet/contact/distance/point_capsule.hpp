#pragma once
/// @file Signed distance of a point to a capsule (a segment swept by a sphere: a rigid strut, a
/// boom, a thick cable end), with the outward normal and the Hessian; the gap of a sphere of
/// radius r is distance − r.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Signed distance of a point to a capsule and its derivatives with respect to the point.
struct PointCapsuleDistance {
  double distance = 0.0;   ///< φ = |p − x_s| − ρ (m), negative inside
  Vector3d closest_point;  ///< x_s + ρ n, on the surface (m)
  Vector3d normal;         ///< n = ∂φ/∂p, outward, unit
  Matrix3d hessian;        ///< ∂²φ/∂p² (1/m), as the point–segment distance's
  bool on_axis = false;    ///< p on the axis segment: n is a fixed perpendicular, Hessian 0
};

/// Signed distance of the point p to the capsule of centre c, unit axis a, half length H ≥ 0 and
/// radius ρ > 0 (m): with the axis segment [c − H a, c + H a] and its closest point x_s to p
/// (CalcPointSegmentDistance), φ = |p − x_s| − ρ, n = (p − x_s)/|p − x_s| and
/// ∂²φ/∂p² = (I − a aᵀ − n nᵀ)/|p − x_s| beside the cylindrical part, (I − n nᵀ)/|p − x_s| at
/// the hemispherical ends (CalcPointSegmentHessian). φ is C¹ everywhere but on the axis, where
/// n is a perpendicular of a (AnyUnitPerpendicular) and the Hessian is 0. Precondition: |a| = 1
/// (not checked). Ericson (2005), §4.5.
PointCapsuleDistance CalcPointCapsuleDistance(const Vector3d& p, const Vector3d& center,
                                              const Vector3d& axis, double half_length,
                                              double radius);

}  // namespace ancfnet
