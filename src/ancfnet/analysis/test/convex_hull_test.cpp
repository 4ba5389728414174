// The convex hull's inside test and the fraction of a ball it encloses, on geometries whose answer
// is known: a cube round a ball (1), a half-space through its centre (½), a ball outside (0), a
// flat point set (no volume: 0), a regular polyhedron's facets.

#include "ancfnet/analysis/convex_hull.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// The 8 corners of the box [lower, upper] and, to exercise the points inside, its centre and the
// centres of its faces.
std::vector<Vector3d> BoxPoints(const Vector3d& lower, const Vector3d& upper) {
  std::vector<Vector3d> points;
  for (int i = 0; i < 8; ++i)
    points.emplace_back(i & 1 ? upper.x() : lower.x(), i & 2 ? upper.y() : lower.y(),
                        i & 4 ? upper.z() : lower.z());
  const Vector3d center = 0.5 * (lower + upper);
  points.push_back(center);
  for (int axis = 0; axis < 3; ++axis) {
    Vector3d face = center;
    face[axis] = upper[axis];
    points.push_back(face);
  }
  return points;
}

TEST(ConvexHull, CubeHasSixFaceNormalsAndHoldsItsInterior) {
  const ConvexHull hull(BoxPoints(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)));
  ASSERT_FALSE(hull.empty());
  // Each square face is two triangles with the face's normal.
  EXPECT_EQ(hull.facets().size(), 12u);
  for (const ConvexHull::Facet& f : hull.facets()) {
    EXPECT_NEAR(f.normal.cwiseAbs().maxCoeff(), 1.0, 1e-14);
    EXPECT_NEAR(f.offset, 1.0, 1e-14);
  }
  EXPECT_TRUE(hull.Contains(Vector3d(0.99, -0.99, 0.5)));
  EXPECT_TRUE(hull.Contains(Vector3d(1, 1, 1)));  // a corner: on the boundary
  EXPECT_FALSE(hull.Contains(Vector3d(1.01, 0, 0)));
  EXPECT_FALSE(hull.Contains(Vector3d(0.8, 0.8, 0.8) * 1.3));
}

TEST(ConvexHull, BallInsideACubeOfNodesIsWhollyEnclosed) {
  const ConvexHull hull(BoxPoints(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)));
  EXPECT_EQ(hull.CalcBallFractionInside(Vector3d(0.1, 0, -0.05), 0.8), 1.0);
}

TEST(ConvexHull, HalfSpaceThroughTheCentreEnclosesHalfTheBall) {
  // The hull covers z ≤ 0 of the ball exactly: the symmetric sample splits evenly.
  const ConvexHull hull(BoxPoints(Vector3d(-2, -2, -2), Vector3d(2, 2, 0)));
  EXPECT_DOUBLE_EQ(hull.CalcBallFractionInside(Vector3d::Zero(), 1.0), 0.5);
  EXPECT_DOUBLE_EQ(hull.CalcBallFractionInside(Vector3d::Zero(), 1.0, 10), 0.5);
}

TEST(ConvexHull, SliceOfTheBallMatchesTheCapVolume) {
  // The hull covers z ≤ h of a unit ball: the cap above has volume π (1 − h)² (2 + h)/3, so the
  // fraction inside is 1 − (1 − h)² (2 + h)/4. 40 cells per axis: within 1 %.
  const double h = 0.4;
  const ConvexHull hull(BoxPoints(Vector3d(-2, -2, -2), Vector3d(2, 2, h)));
  const double exact = 1.0 - (1.0 - h) * (1.0 - h) * (2.0 + h) / 4.0;
  EXPECT_NEAR(hull.CalcBallFractionInside(Vector3d::Zero(), 1.0, 40), exact, 0.01);
}

TEST(ConvexHull, BallOutsideTheHullIsNotEnclosed) {
  const ConvexHull hull(BoxPoints(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)));
  EXPECT_EQ(hull.CalcBallFractionInside(Vector3d(3, 0, 0), 0.9), 0.0);
}

TEST(ConvexHull, FlatOrTooFewPointsSpanNoVolume) {
  std::vector<Vector3d> flat;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) flat.emplace_back(i, j, 2.0);
  const ConvexHull hull(flat);
  EXPECT_TRUE(hull.empty());
  EXPECT_FALSE(hull.Contains(Vector3d(2, 2, 2)));
  EXPECT_EQ(hull.CalcBallFractionInside(Vector3d(2, 2, 2), 0.5), 0.0);
  EXPECT_TRUE(ConvexHull({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)}).empty());
  EXPECT_TRUE(ConvexHull({}).empty());
}

TEST(ConvexHull, PointsOnASphereGiveAClosedHullInsideIt) {
  // 200 points on the unit sphere (a Fibonacci lattice) and their centre: every facet is a
  // chord plane (offset < 1) facing out, and the points all lie on or inside every facet.
  std::vector<Vector3d> points{Vector3d::Zero()};
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 200; ++i) {
    const double z = 1.0 - (i + 0.5) / 100.0;
    const double r = std::sqrt(1.0 - z * z);
    points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  const ConvexHull hull(points);
  // Euler: a triangulated sphere of V vertices has 2V − 4 faces.
  EXPECT_EQ(hull.facets().size(), 2u * 200u - 4u);
  for (const ConvexHull::Facet& f : hull.facets()) {
    EXPECT_GT(f.offset, 0.9);
    EXPECT_LT(f.offset, 1.0);
  }
  for (const Vector3d& p : points) EXPECT_TRUE(hull.Contains(p));
  EXPECT_EQ(hull.CalcBallFractionInside(Vector3d::Zero(), 0.9), 1.0);
}

TEST(ConvexHull, RefusesABadBall) {
  const ConvexHull hull(BoxPoints(Vector3d(-1, -1, -1), Vector3d(1, 1, 1)));
  EXPECT_THROW(hull.CalcBallFractionInside(Vector3d::Zero(), 0.0), InputError);
}

}  // namespace
}  // namespace ancfnet
