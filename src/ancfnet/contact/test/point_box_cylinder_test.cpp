#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "ancfnet/contact/distance/point_box.hpp"
#include "ancfnet/contact/distance/point_cylinder.hpp"
#include "ancfnet/contact/test/distance_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::CheckGradientAndHessian;
using test::RandomRotation;
using test::RandomVector;

constexpr double kPi = 3.14159265358979323846;

// Minimum distance from p to samples of a surface given by a parametrisation on a grid.
double ScanSurface(const Vector3d& p, int nu, int nv,
                   const std::function<Vector3d(double, double)>& surface) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= nu; ++i) {
    for (int j = 0; j <= nv; ++j) {
      best = std::min(
          best, (p - surface(static_cast<double>(i) / nu, static_cast<double>(j) / nv)).norm());
    }
  }
  return best;
}

TEST(PointBoxDistance, MatchesSurfaceScan) {
  std::mt19937 rng(51);
  constexpr int kScan = 150;
  double worst_scan = 0.0;
  int inside = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Vector3d h = RandomVector(&rng, 0.2, 1.0);
    const Matrix3d R = RandomRotation(&rng);
    const Vector3d p = c + RandomVector(&rng, -1.5, 1.5);
    const PointBoxDistance d = CalcPointBoxDistance(p, c, h, R);
    double scan = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      const int i1 = (axis + 1) % 3, i2 = (axis + 2) % 3;
      for (double sign : {-1.0, 1.0}) {
        scan = std::min(scan, ScanSurface(p, kScan, kScan, [&](double u, double v) {
                          Vector3d q;
                          q[axis] = sign * h[axis];
                          q[i1] = (2 * u - 1) * h[i1];
                          q[i2] = (2 * v - 1) * h[i2];
                          return Vector3d(c + R * q);
                        }));
      }
    }
    const Vector3d q = R.transpose() * (p - c);
    const bool expect_inside = (q.cwiseAbs() - h).maxCoeff() <= 0.0;
    EXPECT_EQ(d.inside, expect_inside);
    EXPECT_EQ(d.distance <= 0.0, expect_inside);
    inside += expect_inside;
    const double resolution = 0.5 * std::sqrt(2.0) * 2.0 * h.maxCoeff() / kScan;
    EXPECT_LE(std::abs(d.distance), scan + 1e-14);
    EXPECT_LE(scan - std::abs(d.distance), resolution);
    worst_scan = std::max(worst_scan, (scan - std::abs(d.distance)) / resolution);
    // p = x + φ n, x on the surface, n unit.
    EXPECT_NEAR((p - d.closest_point - d.distance * d.normal).norm(), 0.0, 1e-14);
    const Vector3d qx = R.transpose() * (d.closest_point - c);
    EXPECT_NEAR((qx.cwiseAbs() - h).maxCoeff(), 0.0, 1e-14);
    EXPECT_NEAR(d.normal.norm(), 1.0, 1e-14);
  }
  EXPECT_GT(inside, 10);
  std::cout << "[measured] point-box: (scan - |d|)/resolution max " << worst_scan << " (" << inside
            << " inside)\n";
}

TEST(PointBoxDistance, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(52);
  double worst_g = 0.0, worst_h = 0.0;
  int checked = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Vector3d h = RandomVector(&rng, 0.2, 1.0);
    const Matrix3d R = RandomRotation(&rng);
    const Vector3d p = c + RandomVector(&rng, -1.5, 1.5);
    auto eval = [&](const Vector3d& x) { return CalcPointBoxDistance(x, c, h, R); };
    // Key: which axes are clamped and which way, or the nearest face when inside.
    auto key = [&](const Vector3d& x) {
      const Vector3d q = R.transpose() * (x - c);
      int code = 0;
      for (int i = 0; i < 3; ++i) code = 3 * code + (q[i] > h[i] ? 2 : (q[i] < -h[i] ? 0 : 1));
      const Vector3d n_B = R.transpose() * eval(x).normal;
      Index face = 0;
      if (code == 13) {  // inside: the nearest face
        n_B.cwiseAbs().maxCoeff(&face);
        code = 100 + 2 * static_cast<int>(face) + (n_B[face] > 0 ? 1 : 0);
      }
      return code;
    };
    CheckGradientAndHessian(eval, key, p, &worst_g, &worst_h, &checked);
  }
  EXPECT_GT(checked, 150);
  std::cout << "[measured] point-box: gradient FD error " << worst_g << ", Hessian " << worst_h
            << " over " << checked << "\n";
}

TEST(PointBoxDistance, SurfaceAndCentreAreFinite) {
  const Vector3d h(1, 2, 3);
  const Matrix3d R = Matrix3d::Identity();
  PointBoxDistance d = CalcPointBoxDistance(Vector3d::Zero(), Vector3d::Zero(), h, R);
  EXPECT_DOUBLE_EQ(d.distance, -1.0);
  EXPECT_EQ(d.normal, Vector3d::UnitX());
  d = CalcPointBoxDistance(Vector3d(1, 0.5, 0.5), Vector3d::Zero(), h, R);  // on a face
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_EQ(d.normal, Vector3d::UnitX());
  d = CalcPointBoxDistance(Vector3d(1, 2, 3), Vector3d::Zero(), h, R);  // a corner
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_TRUE(d.normal.allFinite() && d.hessian.allFinite());
  d = CalcPointBoxDistance(Vector3d(2, 3, 0), Vector3d::Zero(), h, R);  // near an edge
  EXPECT_NEAR(d.distance, std::sqrt(2.0), 1e-15);
}

TEST(PointCylinderDistance, MatchesSurfaceScan) {
  std::mt19937 rng(61);
  double worst_scan = 0.0;
  int inside = 0, rim = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Matrix3d R = RandomRotation(&rng);
    const Vector3d axis = R.col(2), e1 = R.col(0), e2 = R.col(1);
    const double rho = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    const double H = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    const Vector3d p = c + RandomVector(&rng, -1.5, 1.5);
    const PointCylinderDistance d = CalcPointCylinderDistance(p, c, axis, rho, H);
    constexpr int kAngles = 600, kAlong = 150;
    auto ring = [&](double phi) { return Vector3d(std::cos(phi) * e1 + std::sin(phi) * e2); };
    double scan = ScanSurface(p, kAngles, kAlong, [&](double u, double v) {
      return Vector3d(c + rho * ring(2 * kPi * u) + (2 * v - 1) * H * axis);
    });
    for (double sign : {-1.0, 1.0}) {
      scan = std::min(scan, ScanSurface(p, kAngles, kAlong, [&](double u, double v) {
                        return Vector3d(c + v * rho * ring(2 * kPi * u) + sign * H * axis);
                      }));
    }
    const double z = axis.dot(p - c);
    const double radial = (p - c - z * axis).norm();
    const bool expect_inside = radial <= rho && std::abs(z) <= H;
    EXPECT_EQ(d.inside, expect_inside);
    EXPECT_EQ(d.distance <= 0.0, expect_inside);
    inside += expect_inside;
    rim += d.region == CylinderRegion::kRim;
    const double arc = 2 * kPi * rho / kAngles;
    const double resolution = 0.5 * std::hypot(arc, std::max(2 * H, rho) / kAlong);
    EXPECT_LE(std::abs(d.distance), scan + 1e-14);
    EXPECT_LE(scan - std::abs(d.distance), resolution);
    worst_scan = std::max(worst_scan, (scan - std::abs(d.distance)) / resolution);
    EXPECT_NEAR((p - d.closest_point - d.distance * d.normal).norm(), 0.0, 1e-14);
    EXPECT_NEAR(d.normal.norm(), 1.0, 1e-14);
  }
  EXPECT_GE(inside, 5);
  EXPECT_GT(rim, 10);
  std::cout << "[measured] point-cylinder: (scan - |d|)/resolution max " << worst_scan << " ("
            << inside << " inside, " << rim << " rim)\n";
}

TEST(PointCylinderDistance, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(62);
  double worst_g = 0.0, worst_h = 0.0;
  int checked = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d c = RandomVector(&rng, -1, 1);
    const Vector3d axis = RandomRotation(&rng).col(2);
    const double rho = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    const double H = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
    const Vector3d p = c + RandomVector(&rng, -1.5, 1.5);
    auto eval = [&](const Vector3d& x) { return CalcPointCylinderDistance(x, c, axis, rho, H); };
    auto key = [&](const Vector3d& x) {
      const PointCylinderDistance e = eval(x);
      return 10 * static_cast<int>(e.region) + (e.inside ? 1 : 0);
    };
    CheckGradientAndHessian(eval, key, p, &worst_g, &worst_h, &checked);
  }
  EXPECT_GT(checked, 150);
  std::cout << "[measured] point-cylinder: gradient FD error " << worst_g << ", Hessian " << worst_h
            << " over " << checked << "\n";
}

TEST(PointCylinderDistance, AxisAndSurfaceAreFinite) {
  const Vector3d c = Vector3d::Zero(), a = Vector3d::UnitZ();
  // On the axis inside (nearer the side): φ = −ρ, the fixed perpendicular as normal.
  PointCylinderDistance d = CalcPointCylinderDistance(Vector3d(0, 0, 0.1), c, a, 0.5, 2.0);
  EXPECT_DOUBLE_EQ(d.distance, -0.5);
  EXPECT_NEAR(d.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(d.normal.dot(a), 0.0, 1e-15);
  EXPECT_TRUE(d.hessian.allFinite());
  // On the axis beyond the cap.
  d = CalcPointCylinderDistance(Vector3d(0, 0, -3), c, a, 0.5, 2.0);
  EXPECT_EQ(d.region, CylinderRegion::kCap);
  EXPECT_DOUBLE_EQ(d.distance, 1.0);
  EXPECT_EQ(d.normal, -a);
  // On the side, the cap and the rim: φ = 0.
  EXPECT_EQ(CalcPointCylinderDistance(Vector3d(0.5, 0, 1), c, a, 0.5, 2.0).distance, 0.0);
  EXPECT_EQ(CalcPointCylinderDistance(Vector3d(0.1, 0, 2), c, a, 0.5, 2.0).distance, 0.0);
  d = CalcPointCylinderDistance(Vector3d(0, 0.5, 2), c, a, 0.5, 2.0);
  EXPECT_EQ(d.distance, 0.0);
  EXPECT_TRUE(d.normal.allFinite() && d.hessian.allFinite());
  // Rim region: distance to the circular edge.
  d = CalcPointCylinderDistance(Vector3d(1.5, 0, 3), c, a, 0.5, 2.0);
  EXPECT_EQ(d.region, CylinderRegion::kRim);
  EXPECT_NEAR(d.distance, std::sqrt(2.0), 1e-15);
}

}  // namespace
}  // namespace ancfnet
