// The deepest point of a segment in each kind of target against closed forms: a sphere and a
// capsule (the closest points of a segment to a point and to a segment), a tilted plane (the
// lower end), a cylinder (the projection on the plane normal to its axis), a box edge (the
// closest point to the edge line), and a faceted sphere against a dense scan of the segment; the
// lower bound of a segment's distance to a mesh where the search stops in a local minimum.

#include "ancfnet/contact/target_distance.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <tuple>

#include "ancfnet/contact/distance/point_segment.hpp"
#include "ancfnet/contact/distance/segment_segment.hpp"
#include "ancfnet/contact/mesh/icosphere.hpp"

namespace ancfnet {
namespace {

const Vector3d kA(-0.4, 0.1, 0.45), kB(0.5, -0.2, 0.33);

ContactTarget Sphere() {
  ContactTarget t;
  t.kind = ContactTarget::Kind::kSphere;
  t.point = Vector3d(0.05, 0.0, 0.0);
  t.radius = 0.3;
  return t;
}

TEST(SegmentTargetDistance, SphereIsTheClosestPointOfTheSegmentToTheCentre) {
  const ContactTarget sphere = Sphere();
  const SegmentTargetDistance d = CalcSegmentTargetDistance(sphere, kA, kB);
  const PointSegmentDistance exact = CalcPointSegmentDistance(sphere.point, kA, kB);
  EXPECT_NEAR(d.t, exact.t, 1e-10);
  EXPECT_NEAR(d.distance, exact.distance - sphere.radius, 1e-14);
  EXPECT_LT((d.normal + exact.direction).norm(), 1e-10);
  EXPECT_LE(d.evaluations, 8);
}

TEST(SegmentTargetDistance, CapsuleIsTheSegmentSegmentDistance) {
  ContactTarget capsule;
  capsule.kind = ContactTarget::Kind::kCapsule;
  capsule.point = Vector3d(0.1, 0.05, 0.0);
  capsule.normal = Vector3d(0.2, 1.0, 0.1).normalized();
  capsule.half_length = 0.2;
  capsule.radius = 0.25;
  const SegmentTargetDistance d = CalcSegmentTargetDistance(capsule, kA, kB);
  const SegmentSegmentDistance exact =
      CalcSegmentSegmentDistance(kA, kB, capsule.point - capsule.half_length * capsule.normal,
                                 capsule.point + capsule.half_length * capsule.normal);
  EXPECT_NEAR(d.t, exact.s, 1e-9);
  EXPECT_NEAR(d.distance, exact.distance - capsule.radius, 1e-14);
}

TEST(SegmentTargetDistance, TiltedPlaneTakesTheLowerEnd) {
  ContactTarget plane;
  plane.normal = Vector3d(0.1, 0.0, 1.0).normalized();
  const SegmentTargetDistance d = CalcSegmentTargetDistance(plane, kA, kB);
  EXPECT_EQ(d.t, kA.dot(plane.normal) < kB.dot(plane.normal) ? 0.0 : 1.0);
  EXPECT_NEAR(d.distance, std::min(kA.dot(plane.normal), kB.dot(plane.normal)), 1e-15);
}

TEST(SegmentTargetDistance, CylinderIsTheDistanceInThePlaneNormalToItsAxis) {
  ContactTarget cylinder;
  cylinder.kind = ContactTarget::Kind::kCylinder;
  cylinder.normal = Vector3d::UnitY();
  cylinder.radius = 0.2;
  cylinder.half_length = 1.0;
  const SegmentTargetDistance d = CalcSegmentTargetDistance(cylinder, kA, kB);
  const Vector3d flat(1.0, 0.0, 1.0);
  const PointSegmentDistance exact =
      CalcPointSegmentDistance(Vector3d::Zero(), kA.cwiseProduct(flat), kB.cwiseProduct(flat));
  EXPECT_NEAR(d.t, exact.t, 1e-10);
  EXPECT_NEAR(d.distance, exact.distance - cylinder.radius, 1e-14);
}

TEST(SegmentTargetDistance, BoxEdgeIsTheDistanceToTheEdgeLine) {
  // A segment above the edge x = z = 0.5 of the unit box, its closest point in the edge's region.
  ContactTarget box;
  box.kind = ContactTarget::Kind::kBox;
  box.half_extents = Vector3d(0.5, 0.5, 0.5);
  const Vector3d a(0.2, 0.1, 0.8), b(0.9, -0.1, 0.4);
  const SegmentTargetDistance d = CalcSegmentTargetDistance(box, a, b);
  const Vector3d flat(1.0, 0.0, 1.0);
  const PointSegmentDistance exact =
      CalcPointSegmentDistance(Vector3d(0.5, 0.0, 0.5), a.cwiseProduct(flat), b.cwiseProduct(flat));
  ASSERT_GT(exact.closest_point.x(), 0.5);
  ASSERT_GT(exact.closest_point.z(), 0.5);
  EXPECT_NEAR(d.t, exact.t, 1e-9);
  EXPECT_NEAR(d.distance, exact.distance, 1e-14);
}

TEST(SegmentTargetDistance, MeshMatchesADenseScanOfTheSegment) {
  ContactTarget mesh;
  mesh.kind = ContactTarget::Kind::kMesh;
  mesh.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.3, 3));
  for (const auto& [a, b] :
       {std::pair{kA, kB}, std::pair{Vector3d(-0.5, 0.0, 0.25), Vector3d(0.5, 0.02, 0.27)}}) {
    const SegmentTargetDistance d = CalcSegmentTargetDistance(mesh, a, b);
    double lowest = 1e300;
    for (int i = 0; i <= 20000; ++i)
      lowest = std::min(lowest, mesh.mesh->CalcDistance(a + i / 20000.0 * (b - a)).distance);
    EXPECT_LE(d.distance, lowest + 1e-12);
    EXPECT_GT(d.distance, lowest - 1e-6);
    // Within the faceting of the sphere (1.4 mm for 1280 triangles of radius 0.3 m).
    const PointSegmentDistance exact = CalcPointSegmentDistance(Vector3d::Zero(), a, b);
    EXPECT_NEAR(d.distance, exact.distance - 0.3, 2e-3);
  }
}

// Two small triangles under a 1 m segment: the farther (0.06 m) right under the sample t = 0.5,
// the nearer (0.04 m) between the samples 0 and 0.25. The search stops at the farther one; the
// lower bound stays below the global minimum of a dense scan, within |Δ|/8 of the lowest sample.
TEST(SegmentTargetDistance, LowerBoundHoldsWhereTheMeshSearchStopsInALocalMinimum) {
  TriangleMesh wells;
  const double half = 5e-4;
  wells.vertices.resize(3, 6);
  for (const auto& [k, x, z] : {std::tuple{0, 0.125, -0.04}, std::tuple{1, 0.5, -0.06}}) {
    wells.vertices.col(3 * k + 0) = Vector3d(x - half, -half, z);
    wells.vertices.col(3 * k + 1) = Vector3d(x + half, -half, z);
    wells.vertices.col(3 * k + 2) = Vector3d(x, half, z);
  }
  wells.triangles.resize(3, 2);
  wells.triangles << 0, 3, 1, 4, 2, 5;
  ContactTarget mesh;
  mesh.kind = ContactTarget::Kind::kMesh;
  mesh.mesh = std::make_shared<const MeshBvh>(std::move(wells));
  const Vector3d a = Vector3d::Zero(), b = Vector3d::UnitX();
  const SegmentTargetDistance d = CalcSegmentTargetDistance(mesh, a, b);
  double lowest = 1e300;
  for (int i = 0; i <= 20000; ++i)
    lowest = std::min(lowest, mesh.mesh->CalcDistance(a + i / 20000.0 * (b - a)).distance);
  EXPECT_NEAR(lowest, 0.04, 1e-9);
  EXPECT_NEAR(d.distance, 0.06, 1e-9) << "the search should stop in the farther well";
  EXPECT_LE(d.lower_bound, lowest);
  EXPECT_NEAR(d.lower_bound, 0.06 - 1.0 / 8.0, 1e-12);
  // A convex target's bound is its minimum.
  const SegmentTargetDistance s = CalcSegmentTargetDistance(Sphere(), kA, kB);
  EXPECT_EQ(s.lower_bound, s.distance);
}

TEST(SegmentTargetDistance, ZeroLengthSegmentIsThePointDistance) {
  const SegmentTargetDistance d = CalcSegmentTargetDistance(Sphere(), kA, kA);
  EXPECT_EQ(d.t, 0.0);
  EXPECT_EQ(d.evaluations, 1);
  EXPECT_EQ(d.distance, CalcPointTargetDistance(Sphere(), kA).distance);
  EXPECT_EQ(d.lower_bound, d.distance);
}

}  // namespace
}  // namespace ancfnet
