// The distance bound of a moving segment (contact/segment_distance_bound.hpp) never shows a pair
// farther than a reach it is within: segments and points on a random walk through a box and a
// closed faceted sphere (inside included, where the distance is negative), the bound from the
// previous position against the distance found now.

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

// Walks a segment of the given length (0: a point) in steps of up to `stride` and returns how
// many steps the bound from the previous position showed farther than `reach` although the
// distance found now is not (wrong), and how many it showed farther (apart).
struct WalkResult {
  int wrong = 0;
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
    const SegmentTargetDistance found = CalcSegmentTargetDistance(target, y0, y1);
    if (bound.ShowsFartherThan(y0, y1, reach)) {
      ++result.apart;
      if (!(found.distance > reach)) ++result.wrong;
    }
    bound = {y0, y1, found.lower_bound};
    x0 = y0;
    x1 = y1;
  }
  return result;
}

TEST(SegmentDistanceBound, NeverExceedsTheDistanceToABox) {
  for (const double length : {0.0, 0.05}) {
    for (const double reach : {0.0, 0.01, 0.1}) {
      const WalkResult r = Walk(Box(), length, 0.02, reach);
      EXPECT_EQ(r.wrong, 0) << "length " << length << ", reach " << reach;
      EXPECT_GT(r.apart, 100) << "the walk should mostly stay apart";
    }
  }
}

TEST(SegmentDistanceBound, NeverExceedsTheSignedDistanceToAClosedMesh) {
  // Points, and capsule axes whose bound is the sampled one (SegmentTargetDistance::lower_bound).
  for (const double length : {0.0, 0.05}) {
    for (const double reach : {-0.05, 0.0, 0.01, 0.1}) {
      const WalkResult r = Walk(FacetedSphere(), length, 0.02, reach);
      EXPECT_EQ(r.wrong, 0) << "length " << length << ", reach " << reach;
      EXPECT_GT(r.apart, 100) << "length " << length << ", reach " << reach;
    }
  }
}

TEST(SegmentDistanceBound, WithoutADistanceItBoundsNothing) {
  const SegmentDistanceBound bound;
  EXPECT_FALSE(bound.ShowsFartherThan(Vector3d::Zero(), Vector3d::UnitX(), -1e300));
}

}  // namespace
}  // namespace ancfnet
