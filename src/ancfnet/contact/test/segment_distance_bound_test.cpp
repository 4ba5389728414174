// The distance bound of a moving segment (contact/segment_distance_bound.hpp) never exceeds the
// distance it bounds: segments and points on a random walk through a box and a closed faceted
// sphere (inside included, where the distance is negative), the bound from the previous
// position against the distance found now.

#include "ancfnet/contact/segment_distance_bound.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/target_distance.hpp"

namespace ancfnet {
namespace {

ContactTarget Box() {
  ContactTarget t;
  t.kind = ContactTarget::Kind::kBox;
  t.half_extents = Vector3d(0.3, 0.2, 0.25);
  return t;
}

ContactTarget FacetedSphere() {
  ContactTarget t;
  t.kind = ContactTarget::Kind::kMesh;
  t.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.3, 2));
  return t;
}

// Walks a segment of the given length (0: a point) in steps of up to `stride` and returns the
// largest excess of the bound over the distance found after each step, and how many steps the
// bound alone showed apart from `reach`.
struct WalkResult {
  double largest_excess = -1.0;
  int apart = 0;
};
WalkResult Walk(const ContactTarget& target, double length, double stride, double reach) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vector3d x0(0.5, 0.1, -0.2);
  Vector3d x1 = x0 + length * Vector3d(0.6, 0.8, 0.0);
  SegmentDistanceBound bound;
  WalkResult result;
  for (int i = 0; i < 4000; ++i) {
    const Vector3d y0 = (x0 + stride * Vector3d(uniform(random), uniform(random), uniform(random)))
                            .cwiseMax(-0.6)
                            .cwiseMin(0.6);
    const Vector3d y1 =
        y0 + length * Vector3d(uniform(random), uniform(random), uniform(random)).normalized();
    const double lower = bound.LowerBound(y0, y1);
    const double distance = CalcSegmentTargetDistance(target, y0, y1).distance;
    result.largest_excess = std::max(result.largest_excess, lower - distance);
    if (lower > reach) ++result.apart;
    bound = {y0, y1, distance};
    x0 = y0;
    x1 = y1;
  }
  return result;
}

TEST(SegmentDistanceBound, NeverExceedsTheDistanceToABox) {
  for (const double length : {0.0, 0.05}) {
    const WalkResult r = Walk(Box(), length, 0.02, 0.01);
    EXPECT_LE(r.largest_excess, 0.0) << "length " << length;
    EXPECT_GT(r.apart, 400) << "the walk should mostly stay apart";
  }
}

TEST(SegmentDistanceBound, NeverExceedsTheSignedDistanceToAClosedMesh) {
  const WalkResult r = Walk(FacetedSphere(), 0.0, 0.02, 0.01);
  EXPECT_LE(r.largest_excess, 0.0);
  EXPECT_GT(r.apart, 400);
}

TEST(SegmentDistanceBound, WithoutADistanceItBoundsNothing) {
  const SegmentDistanceBound bound;
  EXPECT_FALSE(bound.LowerBound(Vector3d::Zero(), Vector3d::UnitX()) > -1e300);
}

}  // namespace
}  // namespace ancfnet
