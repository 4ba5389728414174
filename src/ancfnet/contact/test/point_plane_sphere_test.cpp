#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "ancfnet/contact/distance/point_plane.hpp"
#include "ancfnet/contact/distance/point_sphere.hpp"
#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::CentralGradient;
using test::CentralJacobian;
using test::RandomVector;

TEST(PointPlaneDistance, SignedDistanceAndGradient) {
  std::mt19937 rng(11);
  for (int k = 0; k < 200; ++k) {
    const Vector3d p = RandomVector(&rng, -2, 2);
    const Vector3d o = RandomVector(&rng, -1, 1);
    const Vector3d n = RandomVector(&rng, -1, 1).normalized();
    const PointPlaneDistance d = CalcPointPlaneDistance(p, o, n);
    // The foot lies on the plane and p − x is along n with length |d|.
    EXPECT_NEAR(n.dot(d.closest_point - o), 0.0, 1e-14);
    EXPECT_NEAR((p - d.closest_point - d.distance * n).norm(), 0.0, 1e-14);
    const Vector3d fd = CentralGradient<3>(
        [&](const Vector3d& x) { return CalcPointPlaneDistance(x, o, n).distance; }, p, 1e-6);
    EXPECT_LT((fd - d.gradient_p).norm(), 1e-9);
  }
  // Below the plane is negative.
  EXPECT_DOUBLE_EQ(
      CalcPointPlaneDistance(Vector3d(0, 0, -0.25), Vector3d::Zero(), Vector3d::UnitZ()).distance,
      -0.25);
}

TEST(PointSphereDistance, DistanceGradientAndHessian) {
  std::mt19937 rng(12);
  double worst_g = 0.0, worst_h = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const double radius = std::uniform_real_distribution<double>(0.1, 1.0)(rng);
    // Points inside and outside, none within 0.05 R of the centre.
    Vector3d p = c + RandomVector(&rng, -2, 2);
    if ((p - c).norm() < 0.05 * radius) p = c + Vector3d(0.5 * radius, 0, 0);
    const PointSphereDistance d = CalcPointSphereDistance(p, c, radius);
    EXPECT_NEAR(d.distance, (p - c).norm() - radius, 1e-14);
    EXPECT_NEAR((d.closest_point - c).norm(), radius, 1e-14);
    EXPECT_NEAR((p - d.closest_point - d.distance * d.normal).norm(), 0.0, 1e-13);
    const double h = 1e-6;
    const Vector3d fd = CentralGradient<3>(
        [&](const Vector3d& x) { return CalcPointSphereDistance(x, c, radius).distance; }, p, h);
    const Matrix3d fdh = CentralJacobian(
        [&](const Vector3d& x) { return CalcPointSphereDistance(x, c, radius).normal; }, p, h);
    const double eg = (fd - d.normal).norm();
    const double eh = (fdh - d.hessian).norm() / std::max(1.0, d.hessian.norm());
    worst_g = std::max(worst_g, eg);
    worst_h = std::max(worst_h, eh);
    EXPECT_LT(eg, 1e-6);
    EXPECT_LT(eh, 1e-6);
  }
  std::cout << "[measured] point-sphere: gradient FD error " << worst_g
            << ", Hessian FD relative error " << worst_h << "\n";
}

TEST(PointSphereDistance, CentreAndSurfaceAreFinite) {
  const Vector3d c(0.3, -0.2, 1.0);
  const PointSphereDistance at_c = CalcPointSphereDistance(c, c, 0.5);
  EXPECT_TRUE(at_c.at_center);
  EXPECT_DOUBLE_EQ(at_c.distance, -0.5);
  EXPECT_EQ(at_c.normal, Vector3d::UnitZ());
  EXPECT_TRUE(at_c.hessian.allFinite());
  EXPECT_TRUE(at_c.closest_point.allFinite());
  // A point 1e-14 from the centre is still "at the centre"; one 1e-6 away is not.
  EXPECT_TRUE(CalcPointSphereDistance(c + Vector3d(1e-14, 0, 0), c, 0.5).at_center);
  const PointSphereDistance near_c = CalcPointSphereDistance(c + Vector3d(0, 1e-6, 0), c, 0.5);
  EXPECT_FALSE(near_c.at_center);
  EXPECT_NEAR((near_c.normal - Vector3d::UnitY()).norm(), 0.0, 1e-12);
  // Zero radius at the centre: a point target, still finite.
  EXPECT_TRUE(CalcPointSphereDistance(c, c, 0.0).normal.allFinite());
  // On the surface: d = 0.
  const PointSphereDistance on = CalcPointSphereDistance(c + Vector3d(0, 0, 0.5), c, 0.5);
  EXPECT_NEAR(on.distance, 0.0, 1e-15);
  EXPECT_TRUE(on.hessian.allFinite());
}

}  // namespace
}  // namespace ancfnet
