// Net metrics against exact values: projected areas of convex and non-convex polygons in any
// orientation, far from the origin too; centroids; distance travelled along an axis.

#include "ancfnet/analysis/net_metrics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

constexpr double kTol = 1e-12;

// An L-shaped hexagon of area 3 in the plane z = 0: the unit square at (1, 1) is cut from a
// 2 × 2 square. Non-convex at (1, 1).
std::vector<Vector3d> LShape() {
  return {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
}

std::vector<Vector3d> Transformed(const std::vector<Vector3d>& polygon, const Matrix3d& rotation,
                                  const Vector3d& offset) {
  std::vector<Vector3d> out;
  for (const Vector3d& p : polygon) out.push_back(rotation * p + offset);
  return out;
}

TEST(NetMetrics, MouthAreaOfANonConvexPolygonIsExact) {
  std::vector<Vector3d> polygon = LShape();
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d::UnitZ()), 3.0, kTol);
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d(0, 0, -2)), 3.0, kTol);  // any length, either sign
  std::reverse(polygon.begin(), polygon.end());                        // clockwise: same area
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d::UnitZ()), 3.0, kTol);
  std::rotate(polygon.begin(), polygon.begin() + 2, polygon.end());  // any starting vertex
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d::UnitZ()), 3.0, kTol);
  // Seen edge-on, the polygon has no area.
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d::UnitX()), 0.0, kTol);
  EXPECT_NEAR(CalcMouthArea(polygon, Vector3d(1, -1, 0)), 0.0, kTol);
}

TEST(NetMetrics, MouthAreaInAnyOrientationIsTheAreaTimesTheCosine) {
  const Matrix3d rotation =
      Eigen::AngleAxisd(2.1, Vector3d(-0.3, 1.0, 0.4).normalized()).toRotationMatrix();
  const std::vector<Vector3d> polygon = Transformed(LShape(), rotation, Vector3d(-4, 5, 0.5));
  const Vector3d normal = rotation.col(2), in_plane = rotation.col(0);
  for (double theta : {0.0, 0.4, 1.2, std::numbers::pi / 2, 2.5}) {
    const Vector3d axis = std::cos(theta) * normal + std::sin(theta) * in_plane;
    EXPECT_NEAR(CalcMouthArea(polygon, 3.0 * axis), 3.0 * std::abs(std::cos(theta)), kTol);
  }
}

TEST(NetMetrics, MouthAreaOfARegularPolygon) {
  // A regular n-gon of circumradius R has area (n/2) R² sin(2π/n).
  const double radius = 1.7;
  for (int n : {3, 4, 7, 64}) {
    std::vector<Vector3d> polygon;
    for (int k = 0; k < n; ++k) {
      const double phi = 2 * std::numbers::pi * k / n;
      polygon.emplace_back(radius * std::cos(phi), radius * std::sin(phi), 0.0);
    }
    EXPECT_NEAR(CalcMouthArea(polygon, Vector3d::UnitZ()),
                0.5 * n * radius * radius * std::sin(2 * std::numbers::pi / n), kTol);
  }
}

TEST(NetMetrics, MouthAreaIsAccurateFarFromTheOrigin) {
  // A net of 1 m² about 7000 km from the origin, as in an Earth-centred frame: products of
  // absolute coordinates (~5e13 m²) would leave an error of about 1e-2 m².
  const Vector3d far(7.0e6, 1.3e6, -2.1e6);
  const Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Vector3d(1.0, 1.0, 1.0).normalized()).toRotationMatrix();
  const std::vector<Vector3d> square =
      Transformed({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, rotation, far);
  EXPECT_NEAR(CalcMouthArea(square, rotation.col(2)), 1.0, 1e-8);
  EXPECT_NEAR(CalcMouthArea(Transformed(LShape(), rotation, far), rotation.col(2)), 3.0, 1e-8);
}

TEST(NetMetrics, MouthAreaOfDegenerateInputs) {
  EXPECT_EQ(CalcMouthArea({}, Vector3d::UnitZ()), 0.0);
  EXPECT_EQ(CalcMouthArea({Vector3d::UnitX(), Vector3d::UnitY()}, Vector3d::UnitZ()), 0.0);
  EXPECT_THROW(CalcMouthArea(LShape(), Vector3d::Zero()), InputError);
  EXPECT_THROW(CalcMouthArea(LShape(), Vector3d(0, NAN, 1)), InputError);
}

TEST(NetMetrics, CentroidIsMassWeighted) {
  EXPECT_TRUE(CalcCentroid({{0, 0, 0}, {4, 0, 0}}, {3.0, 1.0}).isApprox(Vector3d(1, 0, 0), kTol));
  const std::vector<Vector3d> points = {{1, 2, 3}, {-1, 0, 5}, {3, -2, 1}, {1, 4, -1}};
  const Vector3d mean(1, 1, 2);
  EXPECT_TRUE(CalcCentroid(points).isApprox(mean, kTol));
  EXPECT_TRUE(CalcCentroid(points, {0.2, 0.2, 0.2, 0.2}).isApprox(mean, kTol));
  // A zero mass does not count.
  EXPECT_TRUE(CalcCentroid(points, {0.0, 1.0, 0.0, 1.0}).isApprox(Vector3d(0, 2, 2), kTol));
}

TEST(NetMetrics, CentroidRejectsInvalidMasses) {
  const std::vector<Vector3d> points = {Vector3d::UnitX(), Vector3d::UnitY()};
  EXPECT_THROW(CalcCentroid(points, {1.0}), InputError);
  EXPECT_THROW(CalcCentroid({}, {}), InputError);
  EXPECT_THROW(CalcCentroid({}), InputError);
  EXPECT_THROW(CalcCentroid(points, {1.0, -0.5}), InputError);
  EXPECT_THROW(CalcCentroid(points, {0.0, 0.0}), InputError);
  EXPECT_THROW(CalcCentroid(points, {1.0, NAN}), InputError);
}

TEST(NetMetrics, DistanceTravelledCountsMotionAlongTheAxisOnly) {
  const Vector3d start(1, 2, 3);
  EXPECT_NEAR(CalcDistanceTravelled(start, start + Vector3d(0.5, -7, 4), Vector3d(0, 0, 2)), 4.0,
              kTol);
  EXPECT_NEAR(CalcDistanceTravelled(start, start + Vector3d(0, 0, -1), Vector3d::UnitZ()), -1.0,
              kTol);
  const Vector3d axis = Vector3d(1, 1, 0);
  EXPECT_NEAR(CalcDistanceTravelled(start, start + Vector3d(3, 3, 9), axis), 3 * std::sqrt(2.0),
              kTol);
  EXPECT_NEAR(CalcDistanceTravelled(start, start + Vector3d(1, -1, 0), axis), 0.0, kTol);
  EXPECT_THROW(CalcDistanceTravelled(start, start, Vector3d::Zero()), InputError);
}

}  // namespace
}  // namespace ancfnet
