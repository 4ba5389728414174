#include "ancfnet/contact/distance/point_segment.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>

#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::RandomVector;
using test::TernaryMin;

TEST(PointSegmentDistance, MatchesDenseScanAndTernarySearch) {
  std::mt19937 rng(21);
  constexpr int kScan = 20000;
  std::array<int, 3> regions{};
  double worst_scan = 0.0, worst_ternary = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d a = RandomVector(&rng, -1, 1);
    const Vector3d b = RandomVector(&rng, -1, 1);
    const Vector3d p = RandomVector(&rng, -2, 2);
    const PointSegmentDistance d = CalcPointSegmentDistance(p, a, b);
    ++regions[static_cast<int>(d.region)];
    auto at = [&](double t) { return (p - (a + t * (b - a))).norm(); };
    double scan = at(0.0);
    for (int i = 1; i <= kScan; ++i) scan = std::min(scan, at(static_cast<double>(i) / kScan));
    // The scan is never below the minimum, and within half a sample spacing of it.
    const double resolution = 0.5 * (b - a).norm() / kScan;
    EXPECT_LE(d.distance, scan + 1e-14);
    EXPECT_LE(scan - d.distance, resolution);
    const double ternary = TernaryMin(at, 0.0, 1.0);
    EXPECT_NEAR(d.distance, ternary, 1e-10 * (1.0 + d.distance));
    worst_scan = std::max(worst_scan, (scan - d.distance) / resolution);
    worst_ternary = std::max(worst_ternary, std::abs(d.distance - ternary));
    EXPECT_NEAR(at(d.t), d.distance, 1e-14);
    EXPECT_GE(d.t, 0.0);
    EXPECT_LE(d.t, 1.0);
  }
  for (int r : regions) EXPECT_GT(r, 20);  // each of the three regions is exercised
  std::cout << "[measured] point-segment: (scan - d)/resolution max " << worst_scan
            << ", |d - ternary| max " << worst_ternary << "\n";
}

TEST(PointSegmentDistance, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(22);
  int checked = 0;
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    Vector9d x;
    x << RandomVector(&rng, -2, 2), RandomVector(&rng, -1, 1), RandomVector(&rng, -1, 1);
    auto eval = [](const Vector9d& y) {
      return CalcPointSegmentDistance(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6));
    };
    const PointSegmentDistance d = eval(x);
    // Away from region boundaries (and from d = 0, where d has a kink).
    if (d.distance < 1e-2 || (d.t > 0.0 && d.t < 1e-3) || (d.t < 1.0 && d.t > 1.0 - 1e-3)) {
      continue;
    }
    const Vector9d fd =
        test::CentralGradient<9>([&](const Vector9d& y) { return eval(y).distance; }, x, 1e-6);
    const double err = (fd - d.gradient).lpNorm<Eigen::Infinity>();
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-6) << "configuration " << k;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  std::cout << "[measured] point-segment: gradient FD error max " << worst << " over " << checked
            << " configurations\n";
}

TEST(PointSegmentDistance, DegenerateInputIsFinite) {
  const Vector3d a(1, 2, 3);
  // Zero-length segment: the point-point distance.
  const PointSegmentDistance zero = CalcPointSegmentDistance(Vector3d(1, 2, 5), a, a);
  EXPECT_EQ(zero.t, 0.0);
  EXPECT_DOUBLE_EQ(zero.distance, 2.0);
  EXPECT_TRUE(zero.gradient.allFinite());
  // The point on the segment: d = 0 and a unit direction perpendicular to the segment.
  const Vector3d b(3, 2, 3);
  const PointSegmentDistance on = CalcPointSegmentDistance(Vector3d(2, 2, 3), a, b);
  EXPECT_EQ(on.distance, 0.0);
  EXPECT_NEAR(on.t, 0.5, 1e-15);
  EXPECT_NEAR(on.direction.norm(), 1.0, 1e-15);
  EXPECT_NEAR(on.direction.dot(b - a), 0.0, 1e-15);
  EXPECT_TRUE(on.gradient.allFinite());
  // Both: zero-length segment with the point on it.
  const PointSegmentDistance both = CalcPointSegmentDistance(a, a, a);
  EXPECT_EQ(both.distance, 0.0);
  EXPECT_TRUE(both.gradient.allFinite());
  // End regions: the nearest end.
  EXPECT_EQ(CalcPointSegmentDistance(Vector3d(0, 0, 0), a, b).region, PointSegmentRegion::kEndA);
  EXPECT_EQ(CalcPointSegmentDistance(Vector3d(9, 0, 0), a, b).region, PointSegmentRegion::kEndB);
}

}  // namespace
}  // namespace ancfnet
