#pragma once
/// @file A moment M acting on an ANCF cable through its slope a = r': the virtual work
/// δW = M · (a × δa)/|a|² gives the slope force Q = (M × a)/|a|² (docs/theory.md, "Point
/// moment"). The cable carries no torsion, so the component of M along a does no work.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Q = (M × a)/|a|² (N). Precondition: a ≠ 0.
inline Vector3d CalcSlopeMomentForce(const Vector3d& moment, const Vector3d& a) {
  return moment.cross(a) / a.squaredNorm();
}

/// ∂Q/∂a = M̃/|a|² − 2 (M × a) aᵀ/|a|⁴ at fixed M (N).
inline Matrix3d CalcSlopeMomentJacobian(const Vector3d& moment, const Vector3d& a) {
  const double g = a.squaredNorm();
  Matrix3d skew_m;
  skew_m << 0.0, -moment.z(), moment.y(), moment.z(), 0.0, -moment.x(), -moment.y(), moment.x(),
      0.0;
  return skew_m / g - 2.0 / (g * g) * moment.cross(a) * a.transpose();
}

}  // namespace ancfnet
