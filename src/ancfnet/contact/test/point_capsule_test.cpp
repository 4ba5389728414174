#include "ancfnet/contact/distance/point_capsule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::CheckGradientAndHessian;
using test::RandomRotation;
using test::RandomVector;
using test::TernaryMin;

// A capsule is the set of points within ρ of its axis segment: φ = min_t |p − x(t)| − ρ, found
// here by ternary search (the distance to a segment is convex in t), apart from the code tested.
TEST(PointCapsuleDistance, MatchesTheDistanceToTheSweptSegment) {
  std::mt19937 rng(61);
  int inside = 0;
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Vector3d a = RandomRotation(&rng).col(0);
    const double half_length = k % 10 == 0 ? 0.0 : 0.8 * (k % 7) / 7.0;
    const double radius = 0.2 + 0.05 * (k % 9);
    const Vector3d p = c + RandomVector(&rng, -1.0, 1.0);
    const PointCapsuleDistance d = CalcPointCapsuleDistance(p, c, a, half_length, radius);
    const double expected =
        TernaryMin([&](double t) { return (p - (c + t * a)).norm(); }, -half_length, half_length) -
        radius;
    EXPECT_NEAR(d.distance, expected, 1e-10);
    worst = std::max(worst, std::abs(d.distance - expected));
    inside += d.distance < 0.0;
    // p = x + φ n with x on the surface: within ρ of the axis, n unit.
    EXPECT_NEAR((p - d.closest_point - d.distance * d.normal).norm(), 0.0, 1e-13);
    EXPECT_NEAR(d.normal.norm(), 1.0, 1e-14);
  }
  EXPECT_GT(inside, 15);
  std::cout << "[measured] point-capsule: |φ − ternary| max " << worst << " (" << inside
            << " inside)\n";
}

TEST(PointCapsuleDistance, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(62);
  double worst_g = 0.0, worst_h = 0.0;
  int checked = 0;
  for (int k = 0; k < 300; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Vector3d a = RandomRotation(&rng).col(0);
    const double half_length = 0.5, radius = 0.2;
    const Vector3d p = c + RandomVector(&rng, -1.5, 1.5);
    auto eval = [&](const Vector3d& x) {
      return CalcPointCapsuleDistance(x, c, a, half_length, radius);
    };
    // Key: beside the cylindrical part (0) or past one end (±1), where the Hessian jumps.
    auto key = [&](const Vector3d& x) {
      const double z = a.dot(x - c);
      return z > half_length ? 1 : (z < -half_length ? -1 : 0);
    };
    CheckGradientAndHessian(eval, key, p, &worst_g, &worst_h, &checked);
  }
  EXPECT_GT(checked, 250);
  std::cout << "[measured] point-capsule: gradient FD error " << worst_g << ", Hessian " << worst_h
            << " over " << checked << "\n";
}

TEST(PointCapsuleDistance, OnTheAxisIsFinite) {
  const PointCapsuleDistance d =
      CalcPointCapsuleDistance(Vector3d(0, 0, 0.3), Vector3d::Zero(), Vector3d::UnitZ(), 0.5, 0.2);
  EXPECT_TRUE(d.on_axis);
  EXPECT_DOUBLE_EQ(d.distance, -0.2);
  EXPECT_NEAR(d.normal.dot(Vector3d::UnitZ()), 0.0, 1e-15);  // a perpendicular of the axis
  EXPECT_TRUE(d.hessian.isZero());
  // A zero-length capsule is a sphere: (I − n nᵀ)/|p − c|.
  const Vector3d p(0.3, 0.4, 0.0);
  const PointCapsuleDistance s =
      CalcPointCapsuleDistance(p, Vector3d::Zero(), Vector3d::UnitX(), 0.0, 0.2);
  EXPECT_NEAR(s.distance, 0.3, 1e-15);
  const Vector3d n = p / 0.5;
  EXPECT_TRUE(s.hessian.isApprox((Matrix3d::Identity() - n * n.transpose()) / 0.5, 1e-14));
}

}  // namespace
}  // namespace ancfnet
