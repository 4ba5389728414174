// The section lock of a knot of beam threads (forces/section_lock.hpp): its gradient and Hessian
// against central differences at a deformed, turned state; W = k (1 − cos θ) for a relative
// rotation θ of rigid sections; no energy for a rotation of both together, nor for stretch of
// the sections along the thread.

#include "ancfnet/forces/section_lock.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace ancfnet {
namespace {

constexpr double kStiffness = 3.7;  // N m/rad

// An orthonormal frame [d₁ d₂ d₃], d₁ = d₂ × d₃, turned by `angle` about `axis`.
Matrix3d TurnedFrame(double angle, const Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// x = (d₂, d₃) of frame A rotated by R_A, then (d₂, d₃) of frame B rotated by R_B.
Vector12d Sections(const Matrix3d& rotation_a, const Matrix3d& a, const Matrix3d& rotation_b,
                   const Matrix3d& b) {
  Vector12d x;
  x << rotation_a * a.col(1), rotation_a * a.col(2), rotation_b * b.col(1), rotation_b * b.col(2);
  return x;
}

const Matrix3d kFirst = TurnedFrame(0.3, Vector3d(1, 2, 3));
const Matrix3d kSecond = TurnedFrame(1.9, Vector3d(-2, 1, 0.5));  // a thread at an angle

TEST(SectionLock, GradientAndHessianMatchCentralDifferences) {
  // Sections turned apart, stretched and sheared: a generic state.
  Vector12d x = Sections(TurnedFrame(0.4, Vector3d(0, 1, 1)), kFirst,
                         TurnedFrame(-0.7, Vector3d(1, 0, 2)), kSecond);
  for (int i = 0; i < 12; ++i) x[i] += 0.05 * std::sin(3.0 * i + 1.0);
  const SectionLockResult at = CalcSectionLock(kStiffness, kFirst, kSecond, x, true);
  const double h = 1e-6;
  Vector12d gradient;
  Matrix12d hessian;
  for (int j = 0; j < 12; ++j) {
    Vector12d plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const SectionLockResult p = CalcSectionLock(kStiffness, kFirst, kSecond, plus, false);
    const SectionLockResult m = CalcSectionLock(kStiffness, kFirst, kSecond, minus, false);
    gradient[j] = (p.energy - m.energy) / (2 * h);
    hessian.col(j) = (p.gradient - m.gradient) / (2 * h);
  }
  ASSERT_GT(at.gradient.norm(), 0.1);
  EXPECT_LT((at.gradient - gradient).norm(), 1e-8 * at.gradient.norm());
  EXPECT_LT((at.stiffness - hessian).norm(), 1e-7 * at.stiffness.norm());
  EXPECT_LT((at.stiffness - at.stiffness.transpose()).norm(), 1e-14 * at.stiffness.norm());
}

TEST(SectionLock, RelativeRotationStoresOneMinusCosineEnergy) {
  for (const double angle : {1e-3, 0.2, 1.0, 2.5}) {
    const Matrix3d common = TurnedFrame(0.8, Vector3d(3, -1, 2));
    const Matrix3d relative = TurnedFrame(angle, Vector3d(0.3, 1, -0.4));
    const Vector12d x = Sections(common, kFirst, common * relative, kSecond);
    const double energy = CalcSectionLock(kStiffness, kFirst, kSecond, x, false).energy;
    EXPECT_NEAR(energy, kStiffness * (1.0 - std::cos(angle)), 1e-13 * kStiffness) << angle;
  }
}

TEST(SectionLock, RigidRotationOfBothAndStretchAlongTheThreadsCostNothing) {
  const Matrix3d common = TurnedFrame(2.2, Vector3d(1, 1, -1));
  const SectionLockResult rotated =
      CalcSectionLock(kStiffness, kFirst, kSecond, Sections(common, kFirst, common, kSecond), true);
  EXPECT_LT(rotated.energy, 1e-28);
  EXPECT_LT(rotated.gradient.norm(), 1e-14);
  // The lock reads r_y, r_z only: r_x (the thread's stretch and shear) is not among its
  // coordinates. At rest, a small relative rotation δθ stores ½ k δθ².
  const Vector3d axis = Vector3d(0.2, -1, 0.7).normalized();
  const double small = 1e-4;
  const Vector12d x = Sections(common, kFirst, common * TurnedFrame(small, axis), kSecond);
  const Vector12d dx = x - Sections(common, kFirst, common, kSecond);
  EXPECT_NEAR(0.5 * dx.dot(rotated.stiffness * dx), 0.5 * kStiffness * small * small,
              1e-6 * kStiffness * small * small);
}

}  // namespace
}  // namespace ancfnet
