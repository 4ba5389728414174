#pragma once
/// @file Metrics of a net in flight: the mouth area and the centroid.

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Area (m²) of the closed polygon `polygon` projected on the plane normal to `axis`
/// (shoelace formula in an orthonormal basis of that plane; |area|, any polygon without
/// self-intersections, convex or not).
double CalcMouthArea(const std::vector<Vector3d>& polygon, const Vector3d& axis);

/// Mass-weighted centroid Σ m_i r_i / Σ m_i (m); the plain mean when every mass is equal.
Vector3d CalcCentroid(const std::vector<Vector3d>& points, const std::vector<double>& masses);

}  // namespace ancfnet
