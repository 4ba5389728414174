#pragma once
/// @file Metrics of a net in flight: the mouth area, the centroid and the distance travelled.
/// Pure functions on knot positions (m); they know nothing of the model.

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Area (m²) of the closed polygon `polygon` (vertices in order, the last joined to the first)
/// projected on the plane normal to `axis` (any non-zero length):
///
///   A = ½ |Σᵢ (pᵢ × pᵢ₊₁) · â|,  pᵢ = rᵢ − r₀,  â = axis / |axis|,
///
/// which is the shoelace formula ½ |Σᵢ (xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ)| written in any orthonormal basis
/// (e₁, e₂) of that plane with e₁ × e₂ = â. Valid for any simple polygon, convex or not, and for
/// either direction of travel; a self-intersecting polygon gives the net signed area of its
/// loops. Measuring from the first vertex keeps the sum accurate far from the world origin. Fewer
/// than three vertices give 0. Throws InputError for a zero or non-finite axis.
double CalcMouthArea(const std::vector<Vector3d>& polygon, const Vector3d& axis);

/// Mass-weighted centroid Σ mᵢ rᵢ / Σ mᵢ (m) of `points` (m) with `masses` (kg); the plain mean
/// when every mass is equal. Throws InputError when the sizes differ, the list is empty, a mass
/// is negative or the total mass is not positive.
Vector3d CalcCentroid(const std::vector<Vector3d>& points, const std::vector<double>& masses);

/// Mean position (1/N) Σ rᵢ (m) of `points` (m): the centroid of equal masses. Throws InputError
/// for an empty list.
Vector3d CalcCentroid(const std::vector<Vector3d>& points);

/// Signed distance (m) travelled along `axis` (any non-zero length) from `start` to `now`, both
/// in m: d = (now − start) · axis / |axis|. Motion across the axis does not count. Throws
/// InputError for a zero or non-finite axis.
double CalcDistanceTravelled(const Vector3d& start, const Vector3d& now, const Vector3d& axis);

}  // namespace ancfnet
