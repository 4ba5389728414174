#pragma once
/// @file Axis-aligned bounding box.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

struct Aabb {
  Vector3d min = Vector3d::Zero();  ///< m
  Vector3d max = Vector3d::Zero();  ///< m

  /// The box of a segment [a, b] swept by a sphere of radius r, grown by `margin` on every side.
  static Aabb OfCapsule(const Vector3d& a, const Vector3d& b, double r, double margin) {
    const double grow = r + margin;
    return {a.cwiseMin(b).array() - grow, a.cwiseMax(b).array() + grow};
  }
  /// The squared distance of the point p from the box (0 inside).
  double SquaredDistanceTo(const Vector3d& p) const {
    return (p - p.cwiseMax(min).cwiseMin(max)).squaredNorm();
  }
  bool Overlaps(const Aabb& o) const {
    return (min.array() <= o.max.array()).all() && (o.min.array() <= max.array()).all();
  }
};

}  // namespace ancfnet
