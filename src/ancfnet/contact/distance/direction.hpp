#pragma once
/// @file Unit directions with a defined answer for degenerate input, shared by the distance
/// functions: where the vector between two closest points vanishes, the contact direction is
/// not defined by the geometry, and each function picks one with these helpers (never NaN).

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// A unit vector perpendicular to v: v × e_k normalised, where e_k is the basis vector along
/// v's smallest component (so the cross product has norm ≥ |v|·√(2/3)). For v = 0 returns e_z.
Vector3d AnyUnitPerpendicular(const Vector3d& v);

/// v/|v| where |v| > 0, else the given fallback (assumed unit).
Vector3d NormalizedOr(const Vector3d& v, const Vector3d& fallback);

}  // namespace ancfnet
