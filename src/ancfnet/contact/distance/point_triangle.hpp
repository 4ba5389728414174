#pragma once
/// @file Closest point of a triangle (a face of a mesh target) to a point, with the region that
/// holds it and the gradient of the distance with respect to the point and the vertices.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// The feature of the triangle that holds the closest point.
enum class TriangleRegion {
  kFace,
  kEdgeAB,
  kEdgeBC,
  kEdgeCA,
  kVertexA,
  kVertexB,
  kVertexC,
};

/// Closest point of a triangle and the derivatives of the distance.
struct PointTriangleDistance {
  Vector3d barycentric;    ///< (λa, λb, λc) ≥ 0, summing to 1: x = λa a + λb b + λc c
  Vector3d closest_point;  ///< x (m)
  double distance = 0.0;   ///< d = |p − x| (m), ≥ 0
  Vector3d direction;      ///< u = (p − x)/d, unit, from the triangle to the point
  Vector12d gradient;      ///< ∂d/∂[p, a, b, c] = [u, −λa u, −λb u, −λc u]
  TriangleRegion region = TriangleRegion::kFace;
};

/// Closest point of the triangle (a, b, c) to the point p (m). With n = (b − a) × (c − a), the
/// projection of p on the plane has the barycentric coordinates
///   λb = ((p − a) × (c − a))·n/|n|²,  λc = ((b − a) × (p − a))·n/|n|²,  λa = 1 − λb − λc;
/// if all three are ≥ 0 the closest point is that projection (region kFace); otherwise it lies
/// on the boundary and is the nearest of the three point–segment closest points (an edge, or a
/// vertex where the segment parameter is clamped). Ericson (2005), §5.1.5, gives the same
/// regions by Voronoi tests.
/// Gradient (envelope theorem, the simplex constraints not depending on the coordinates):
/// ∂d/∂p = u, ∂d/∂v_i = −λ_i u. Degenerate input: a triangle whose sin(angle at a) ≤ 10⁻¹²
/// (collinear or repeated vertices) has no face region and is treated as its three edges; a
/// point on the triangle (d = 0) gets u = n/|n| (the one-sided derivative from the side n
/// points to), or a perpendicular of an edge for a degenerate triangle.
PointTriangleDistance CalcPointTriangleDistance(const Vector3d& p, const Vector3d& a,
                                                const Vector3d& b, const Vector3d& c);

/// |p − x|² of the same closest point x, and nothing else: what a search over many triangles
/// compares (a fraction of the cost of CalcPointTriangleDistance, which the search then calls
/// once, for the nearest). The closest point by Ericson's (2005, §5.1.5) Voronoi tests on the
/// dot products d₁ … d₆ of the edges with p − a, p − b, p − c. A degenerate triangle (whose
/// face test divides by zero) falls back to CalcPointTriangleDistance.
double CalcPointTriangleSquaredDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                        const Vector3d& c);

}  // namespace ancfnet
