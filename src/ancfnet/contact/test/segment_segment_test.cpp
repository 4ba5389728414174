#include "ancfnet/contact/distance/segment_segment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::RandomVector;
using test::TernaryMin;

double PairDistance(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0, const Vector3d& q1,
                    double s, double t) {
  return ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).norm();
}

// Checks one configuration against a 401 × 401 scan of (s, t) and a nested ternary search
// (min over t of a convex function is convex in s). Returns (scan − d)/resolution.
double CheckAgainstBruteForce(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                              const Vector3d& q1, double* ternary_error) {
  const SegmentSegmentDistance d = CalcSegmentSegmentDistance(p0, p1, q0, q1);
  constexpr int kScan = 400;
  double scan = PairDistance(p0, p1, q0, q1, 0, 0);
  for (int i = 0; i <= kScan; ++i) {
    for (int j = 0; j <= kScan; ++j) {
      scan = std::min(scan, PairDistance(p0, p1, q0, q1, static_cast<double>(i) / kScan,
                                         static_cast<double>(j) / kScan));
    }
  }
  const double resolution = 0.5 * ((p1 - p0).norm() + (q1 - q0).norm()) / kScan + 1e-300;
  EXPECT_LE(d.distance, scan + 1e-14);
  EXPECT_LE(scan - d.distance, resolution);
  const double ternary = TernaryMin(
      [&](double s) {
        return TernaryMin([&](double t) { return PairDistance(p0, p1, q0, q1, s, t); }, 0, 1);
      },
      0, 1);
  EXPECT_NEAR(d.distance, ternary, 1e-9 * (1.0 + d.distance));
  *ternary_error = std::max(*ternary_error, std::abs(d.distance - ternary));
  // The returned pair is consistent and inside the parameter box.
  EXPECT_GE(d.s, 0.0);
  EXPECT_LE(d.s, 1.0);
  EXPECT_GE(d.t, 0.0);
  EXPECT_LE(d.t, 1.0);
  EXPECT_NEAR(PairDistance(p0, p1, q0, q1, d.s, d.t), d.distance, 1e-14);
  EXPECT_NEAR(d.direction.norm(), 1.0, 1e-14);
  EXPECT_TRUE(d.gradient.allFinite());
  return (scan - d.distance) / resolution;
}

TEST(SegmentSegmentDistance, RandomPairsMatchBruteForce) {
  std::mt19937 rng(31);
  double worst_scan = 0.0, worst_ternary = 0.0;
  int interior_both = 0, clamped = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d p0 = RandomVector(&rng, -1, 1), p1 = RandomVector(&rng, -1, 1);
    const Vector3d q0 = RandomVector(&rng, -1, 1), q1 = RandomVector(&rng, -1, 1);
    worst_scan = std::max(worst_scan, CheckAgainstBruteForce(p0, p1, q0, q1, &worst_ternary));
    const SegmentSegmentDistance d = CalcSegmentSegmentDistance(p0, p1, q0, q1);
    if (d.part_p == SegmentPart::kInterior && d.part_q == SegmentPart::kInterior) {
      ++interior_both;
    } else {
      ++clamped;
    }
  }
  EXPECT_GT(interior_both, 10);
  EXPECT_GT(clamped, 10);
  std::cout << "[measured] segment-segment random: (scan - d)/resolution max " << worst_scan
            << ", |d - ternary| max " << worst_ternary << " (" << interior_both
            << " interior-interior, " << clamped << " clamped)\n";
}

TEST(SegmentSegmentDistance, NearlyParallelAndShortPairsMatchBruteForce) {
  std::mt19937 rng(32);
  double worst_scan = 0.0, worst_ternary = 0.0;
  for (int k = 0; k < 100; ++k) {
    const Vector3d p0 = RandomVector(&rng, -1, 1), p1 = RandomVector(&rng, -1, 1);
    const Vector3d offset = RandomVector(&rng, -0.5, 0.5);
    // Exactly parallel, or within 1e-13 … 1e-3 rad (both sides of the parallel threshold).
    const double tilt = k % 10 == 0 ? 0.0 : std::pow(10.0, -13.0 + 10.0 * (k % 10 - 1) / 8.0);
    const Vector3d shift = (k % 3 - 1) * 0.7 * (p1 - p0);
    const Vector3d q0 = p0 + offset + shift;
    const Vector3d q1 = p1 + offset + shift + tilt * RandomVector(&rng, -1, 1);
    const bool reverse = k % 2 == 1;
    worst_scan = std::max(worst_scan, CheckAgainstBruteForce(p0, p1, reverse ? q1 : q0,
                                                             reverse ? q0 : q1, &worst_ternary));
    // A very short second segment (1e-9 m).
    const Vector3d r0 = RandomVector(&rng, -1, 1);
    worst_scan = std::max(
        worst_scan,
        CheckAgainstBruteForce(p0, p1, r0, r0 + 1e-9 * RandomVector(&rng, -1, 1), &worst_ternary));
  }
  std::cout << "[measured] segment-segment near-parallel/short: (scan - d)/resolution max "
            << worst_scan << ", |d - ternary| max " << worst_ternary << "\n";
}

TEST(SegmentSegmentDistance, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(33);
  int checked = 0;
  double worst = 0.0;
  auto eval = [](const Vector12d& y) {
    return CalcSegmentSegmentDistance(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6),
                                      y.segment<3>(9));
  };
  auto near_bound = [](double x) { return (x > 0 && x < 1e-3) || (x < 1 && x > 1 - 1e-3); };
  for (int k = 0; k < 200; ++k) {
    Vector12d x;
    x << RandomVector(&rng, -1, 1), RandomVector(&rng, -1, 1), RandomVector(&rng, -1, 1),
        RandomVector(&rng, -1, 1);
    const SegmentSegmentDistance d = eval(x);
    if (d.parallel || d.distance < 1e-2 || near_bound(d.s) || near_bound(d.t)) continue;
    const Vector12d fd =
        test::CentralGradient<12>([&](const Vector12d& y) { return eval(y).distance; }, x, 1e-6);
    const double err = (fd - d.gradient).lpNorm<Eigen::Infinity>();
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-6) << "configuration " << k;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  std::cout << "[measured] segment-segment: gradient FD error max " << worst << " over " << checked
            << " configurations\n";
}

TEST(SegmentSegmentDistance, DegenerateCases) {
  const Vector3d o = Vector3d::Zero(), ex = Vector3d::UnitX(), ey = Vector3d::UnitY();
  // Parallel, overlapping on s ∈ [0.5, 1]: the middle of the overlap, s = 0.75, t = 0.25.
  SegmentSegmentDistance d = CalcSegmentSegmentDistance(o, 2 * ex, ex + ey, 3 * ex + ey);
  EXPECT_TRUE(d.parallel);
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_NEAR(d.s, 0.75, 1e-15);
  EXPECT_NEAR(d.t, 0.25, 1e-15);
  EXPECT_NEAR((d.direction + ey).norm(), 0.0, 1e-15);
  // The same, second segment reversed.
  d = CalcSegmentSegmentDistance(o, 2 * ex, 3 * ex + ey, ex + ey);
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_NEAR(d.s, 0.75, 1e-15);
  EXPECT_NEAR(d.t, 0.75, 1e-15);
  // Collinear and disjoint: the nearest ends, distance 1.
  d = CalcSegmentSegmentDistance(o, ex, 2 * ex, 3 * ex);
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_EQ(d.part_p, SegmentPart::kEnd);
  EXPECT_EQ(d.part_q, SegmentPart::kStart);
  EXPECT_TRUE(d.gradient.allFinite());
  // Collinear and overlapping: d = 0, a unit direction perpendicular to both.
  d = CalcSegmentSegmentDistance(o, 2 * ex, ex, 3 * ex);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_NEAR(d.direction.norm(), 1.0, 1e-15);
  EXPECT_NEAR(d.direction.dot(ex), 0.0, 1e-15);
  // Crossing: d = 0 and u = ±(d1 × d2)/|d1 × d2|.
  d = CalcSegmentSegmentDistance(-ex, ex, -ey, ey);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_NEAR(std::abs(d.direction.z()), 1.0, 1e-15);
  EXPECT_NEAR(d.s, 0.5, 1e-15);
  EXPECT_NEAR(d.t, 0.5, 1e-15);
  // Zero-length segments: point-segment and point-point.
  d = CalcSegmentSegmentDistance(ey, ey, -ex, ex);
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_NEAR(d.t, 0.5, 1e-15);
  d = CalcSegmentSegmentDistance(-ex, ex, ey, ey);
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_NEAR(d.s, 0.5, 1e-15);
  d = CalcSegmentSegmentDistance(ey, ey, ex, ex);
  EXPECT_NEAR(d.distance, std::sqrt(2.0), 1e-15);
  d = CalcSegmentSegmentDistance(ey, ey, ey, ey);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_TRUE(d.direction.allFinite());
  EXPECT_TRUE(d.gradient.allFinite());
  // End point touching the other's interior: T junction, d = 0.
  d = CalcSegmentSegmentDistance(-ex, ex, o, ey);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_EQ(d.part_q, SegmentPart::kStart);
  EXPECT_TRUE(d.gradient.allFinite());
}

TEST(CapsuleCapsuleDistance, GapAndSurfacePoints) {
  const Vector3d ex = Vector3d::UnitX(), ey = Vector3d::UnitY(), ez = Vector3d::UnitZ();
  // Crossing axes 1 m apart in z, radii 0.3 and 0.2: gap 0.5.
  const CapsuleCapsuleDistance c = CalcCapsuleCapsuleDistance(-ex + ez, ex + ez, 0.3, -ey, ey, 0.2);
  EXPECT_NEAR(c.gap, 0.5, 1e-15);
  EXPECT_NEAR((c.surface_point_p - 0.7 * ez).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.surface_point_q - 0.2 * ez).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.surface_point_p - c.surface_point_q).norm(), c.gap, 1e-15);
  // Overlapping: negative gap.
  EXPECT_NEAR(CalcCapsuleCapsuleDistance(-ex, ex, 0.3, 0.4 * ez - ey, 0.4 * ez + ey, 0.2).gap, -0.1,
              1e-15);
}

}  // namespace
}  // namespace ancfnet
