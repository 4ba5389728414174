#pragma once
/// @file Distance of a point to a segment (a capsule's axis, a straight piece of thread), with
/// the gradient with respect to the point and both end points.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Which part of the segment holds the closest point.
enum class PointSegmentRegion {
  kEndA,      ///< t = 0: the point projects before a (or the segment has zero length)
  kInterior,  ///< 0 < t < 1: the foot of the perpendicular
  kEndB,      ///< t = 1: the point projects beyond b
};

/// Coordinates [p, a, b] of a point–segment pair, in this order.
using Vector9d = Eigen::Matrix<double, 9, 1>;

/// Closest point of a segment to a point and the derivatives of the distance.
struct PointSegmentDistance {
  double t = 0.0;          ///< closest parameter in [0, 1]: x = a + t (b − a)
  Vector3d closest_point;  ///< x (m)
  double distance = 0.0;   ///< d = |p − x| (m), ≥ 0
  Vector3d direction;      ///< u = (p − x)/d, unit, from the segment to the point
  Vector9d gradient;       ///< ∂d/∂[p, a, b] = [u, −(1 − t) u, −t u]
  PointSegmentRegion region = PointSegmentRegion::kInterior;
};

/// Closest point of the segment [a, b] to the point p (m):
///   t = clamp((p − a)·(b − a)/|b − a|², 0, 1),  x = a + t (b − a),  d = |p − x|.
/// The same gradient formula holds in all three regions: by the envelope theorem the variation
/// of t does not contribute (in the interior u ⊥ b − a; at an end t is fixed), so
///   ∂d/∂p = u, ∂d/∂a = −(1 − t) u, ∂d/∂b = −t u.
/// Degenerate input, each with a defined answer: a zero-length segment (|b − a|² ≤ 10⁻³⁰⁰)
/// gives t = 0, region kEndA and the point–point distance; a point
/// on the segment (d = 0) gives a u perpendicular to b − a (AnyUnitPerpendicular), a one-sided
/// derivative of the non-smooth d. Ericson (2005), §5.1.2.
PointSegmentDistance CalcPointSegmentDistance(const Vector3d& p, const Vector3d& a,
                                              const Vector3d& b);

/// ∂²d/∂p² = ∂u/∂p of a point–segment distance d (1/m), given the result `d` of
/// CalcPointSegmentDistance(p, a, b): in the interior (I − e eᵀ − u uᵀ)/d with e = (b − a)/|b − a|
/// (the distance to a line), at an end (I − u uᵀ)/d (the distance to a point). Zero where d = 0
/// (the 1/d term is unbounded; a zero keeps an iteration matrix finite). docs/theory.md, "Capsule
/// and mesh targets".
Matrix3d CalcPointSegmentHessian(const PointSegmentDistance& d, const Vector3d& a,
                                 const Vector3d& b);

}  // namespace ancfnet
