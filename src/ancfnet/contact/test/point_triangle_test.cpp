#include "ancfnet/contact/distance/point_triangle.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <tuple>

#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::RandomVector;
using test::TernaryMin;

TEST(PointTriangleDistance, MatchesBruteForce) {
  std::mt19937 rng(41);
  constexpr int kScan = 300;
  std::array<int, 7> regions{};
  double worst_scan = 0.0, worst_ternary = 0.0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d a = RandomVector(&rng, -1, 1), b = RandomVector(&rng, -1, 1),
                   c = RandomVector(&rng, -1, 1);
    const Vector3d p = RandomVector(&rng, -1.5, 1.5);
    const PointTriangleDistance d = CalcPointTriangleDistance(p, a, b, c);
    ++regions[static_cast<int>(d.region)];
    auto at = [&](double u, double v) { return (p - (a + u * (b - a) + v * (c - a))).norm(); };
    double scan = at(0, 0);
    for (int i = 0; i <= kScan; ++i) {
      for (int j = 0; i + j <= kScan; ++j) {
        scan = std::min(scan, at(static_cast<double>(i) / kScan, static_cast<double>(j) / kScan));
      }
    }
    // Every point of the triangle is within half a grid cell's longest side of a sample.
    const double resolution =
        0.5 * std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / kScan;
    EXPECT_LE(d.distance, scan + 1e-14);
    EXPECT_LE(scan - d.distance, resolution);
    const double ternary = TernaryMin(
        [&](double u) { return TernaryMin([&](double v) { return at(u, v); }, 0, 1 - u); }, 0, 1);
    EXPECT_NEAR(d.distance, ternary, 1e-9 * (1.0 + d.distance));
    worst_scan = std::max(worst_scan, (scan - d.distance) / resolution);
    worst_ternary = std::max(worst_ternary, std::abs(d.distance - ternary));
    // Barycentric coordinates are a convex combination reproducing the closest point.
    EXPECT_GE(d.barycentric.minCoeff(), 0.0);
    EXPECT_NEAR(d.barycentric.sum(), 1.0, 1e-14);
    EXPECT_NEAR(
        (d.barycentric[0] * a + d.barycentric[1] * b + d.barycentric[2] * c - d.closest_point)
            .norm(),
        0.0, 1e-14);
  }
  EXPECT_GT(regions[static_cast<int>(TriangleRegion::kFace)], 10);
  EXPECT_GT(regions[static_cast<int>(TriangleRegion::kEdgeAB)] +
                regions[static_cast<int>(TriangleRegion::kEdgeBC)] +
                regions[static_cast<int>(TriangleRegion::kEdgeCA)],
            10);
  EXPECT_GT(regions[static_cast<int>(TriangleRegion::kVertexA)] +
                regions[static_cast<int>(TriangleRegion::kVertexB)] +
                regions[static_cast<int>(TriangleRegion::kVertexC)],
            10);
  std::cout << "[measured] point-triangle: (scan - d)/resolution max " << worst_scan
            << ", |d - ternary| max " << worst_ternary << "; regions face/AB/BC/CA/A/B/C";
  for (int r : regions) std::cout << " " << r;
  std::cout << "\n";
}

TEST(PointTriangleDistance, GradientMatchesFiniteDifferences) {
  std::mt19937 rng(42);
  int checked = 0;
  double worst = 0.0;
  auto eval = [](const Vector12d& y) {
    return CalcPointTriangleDistance(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6),
                                     y.segment<3>(9));
  };
  for (int k = 0; k < 200; ++k) {
    Vector12d x;
    x << RandomVector(&rng, -1.5, 1.5), RandomVector(&rng, -1, 1), RandomVector(&rng, -1, 1),
        RandomVector(&rng, -1, 1);
    const PointTriangleDistance d = eval(x);
    if (d.distance < 1e-2) continue;
    // Away from region boundaries: every perturbed evaluation stays in the same region.
    bool same_region = true;
    const Vector12d fd = test::CentralGradient<12>(
        [&](const Vector12d& y) {
          const PointTriangleDistance e = eval(y);
          same_region = same_region && e.region == d.region;
          return e.distance;
        },
        x, 1e-6);
    if (!same_region) continue;
    const double err = (fd - d.gradient).lpNorm<Eigen::Infinity>();
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-6) << "configuration " << k;
    ++checked;
  }
  EXPECT_GT(checked, 150);
  std::cout << "[measured] point-triangle: gradient FD error max " << worst << " over " << checked
            << " configurations\n";
}

TEST(PointTriangleDistance, SquaredDistanceMatchesTheFullQuery) {
  std::mt19937 rng(43);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const Vector3d a = RandomVector(&rng, -1, 1), b = RandomVector(&rng, -1, 1),
                   c = RandomVector(&rng, -1, 1);
    const Vector3d p = RandomVector(&rng, -1.5, 1.5);
    const double d = CalcPointTriangleDistance(p, a, b, c).distance;
    const double error = std::abs(CalcPointTriangleSquaredDistance(p, a, b, c) - d * d);
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-13 * (1.0 + d * d)) << "configuration " << k;
  }
  // Degenerate triangles (collinear, two or three vertices equal) and a point on the face.
  const Vector3d a(0, 0, 0), b(1, 0, 0);
  for (const auto& [p, c, d] : std::array<std::tuple<Vector3d, Vector3d, double>, 5>{{
           {Vector3d(0.5, 1, 0), Vector3d(2, 0, 0), 1.0},
           {Vector3d(3, 0, 0), Vector3d(2, 0, 0), 1.0},
           {Vector3d(0, 0, 2), a, 2.0},
           {Vector3d(0.5, 0, 0.5), b, 0.5},
           {Vector3d(0.2, 0.2, 0), Vector3d(0, 1, 0), 0.0},
       }})
    EXPECT_NEAR(CalcPointTriangleSquaredDistance(p, a, b, c), d * d, 1e-15);
  EXPECT_NEAR(CalcPointTriangleSquaredDistance(Vector3d(0, 0, 2), a, a, a), 4.0, 1e-15);
  std::cout << "[measured] point-triangle: |squared query - d²| max " << worst << "\n";
}

TEST(PointTriangleDistance, DegenerateInputIsFinite) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // In the face: d = 0, direction the face normal.
  PointTriangleDistance d = CalcPointTriangleDistance(Vector3d(0.2, 0.2, 0), a, b, c);
  EXPECT_EQ(d.region, TriangleRegion::kFace);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_NEAR((d.direction - Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  // On an edge: d = 0, still the face normal.
  d = CalcPointTriangleDistance(Vector3d(0.5, -0.0, 0), a, b, c);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_TRUE(d.gradient.allFinite());
  EXPECT_NEAR(d.direction.norm(), 1.0, 1e-15);
  // Above a face, an edge and a vertex.
  EXPECT_EQ(CalcPointTriangleDistance(Vector3d(0.2, 0.2, 1), a, b, c).region,
            TriangleRegion::kFace);
  EXPECT_EQ(CalcPointTriangleDistance(Vector3d(0.5, -1, 1), a, b, c).region,
            TriangleRegion::kEdgeAB);
  EXPECT_EQ(CalcPointTriangleDistance(Vector3d(1, 1, 1), a, b, c).region, TriangleRegion::kEdgeBC);
  EXPECT_EQ(CalcPointTriangleDistance(Vector3d(-1, -1, 0), a, b, c).region,
            TriangleRegion::kVertexA);
  // Collinear vertices: the nearest edge, distance 1.
  d = CalcPointTriangleDistance(Vector3d(0.5, 1, 0), a, b, Vector3d(2, 0, 0));
  EXPECT_NEAR(d.distance, 1.0, 1e-15);
  EXPECT_TRUE(d.gradient.allFinite());
  // All three vertices equal.
  d = CalcPointTriangleDistance(Vector3d(0, 0, 2), a, a, a);
  EXPECT_NEAR(d.distance, 2.0, 1e-15);
  EXPECT_TRUE(d.gradient.allFinite());
  d = CalcPointTriangleDistance(a, a, a, a);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_TRUE(d.direction.allFinite());
}

}  // namespace
}  // namespace ancfnet
