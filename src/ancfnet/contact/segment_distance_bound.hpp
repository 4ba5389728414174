#pragma once
/// @file A lower bound of a moving segment's distance to a rigid shape, from the distance found
/// where the segment was before: a cull that skips distance queries of pairs that cannot touch.

#include <algorithm>
#include <limits>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// The ends x₀, x₁ of a segment (in the shape's frame) when its distance d to the shape was last
/// found. The (signed) distance to a fixed set is 1-Lipschitz in the point, and each point
/// (1 − t) y₀ + t y₁ of the segment now lies within max(|y₀ − x₀|, |y₁ − x₁|) of the point with the
/// same t then, so the distance now is at least d − max(|y₀ − x₀|, |y₁ − x₁|). A pair whose bound
/// exceeds its reach cannot touch: skipping it changes no result. No distance yet: −∞.
struct SegmentDistanceBound {
  Vector3d x0 = Vector3d::Zero();
  Vector3d x1 = Vector3d::Zero();
  double distance = -std::numeric_limits<double>::infinity();

  /// Whether the bound for the segment now at y₀, y₁, less 1e-9 m for the rounding of the
  /// distances it compares, exceeds `reach` (m): d − 10⁻⁹ − reach > max(|y₀ − x₀|, |y₁ − x₁|),
  /// compared squared (no square root: the test runs for every probe and target at every residual).
  bool ShowsFartherThan(const Vector3d& y0, const Vector3d& y1, double reach) const {
    constexpr double kRounding = 1e-9;
    const double margin = distance - kRounding - reach;
    return margin > 0.0 &&
           std::max((y0 - x0).squaredNorm(), (y1 - x1).squaredNorm()) < margin * margin;
  }
};

}  // namespace ancfnet
