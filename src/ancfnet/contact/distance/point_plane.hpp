#pragma once
/// @file Signed distance of a point to a plane (the boundary of a half-space target).

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Signed distance of a point to a plane and its derivatives.
struct PointPlaneDistance {
  double distance = 0.0;   ///< d = n·(p − o) (m): > 0 on the side n points to, < 0 inside
  Vector3d closest_point;  ///< the foot of the perpendicular, p − d n (m)
  Vector3d gradient_p;     ///< ∂d/∂p = n; the Hessian is 0
};

/// Signed distance d = n·(p − o) of the point p_W to the plane through o_W with unit normal
/// n_W (pointing out of the half-space), all in the same frame (m). Precondition: |n| = 1 (not
/// checked; a non-unit n scales d). Ericson (2005), §5.1.1.
PointPlaneDistance CalcPointPlaneDistance(const Vector3d& p, const Vector3d& o, const Vector3d& n);

}  // namespace ancfnet
