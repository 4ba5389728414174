#pragma once
/// @file The cross-product matrix, shared by the elements' Jacobians and the rigid bodies'
/// kinematics.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// The cross-product (skew) matrix ã of a: ã b = a × b.
inline Matrix3d Skew(const Vector3d& a) {
  Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace ancfnet
