#include "ancfnet/forces/spring_damper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// Generic configurations: no symmetry to hide a transposed block or a sign.
const Vector3d kD(0.53, -0.41, 0.37);     // |d| ≈ 0.766 m
const Vector3d kDDot(0.21, 0.34, -0.17);  // m/s
const Vector3d kOmega(0.3, -0.8, 1.1);    // rad/s

struct NamedLaw {
  std::string name;
  ConnectionLaw law;
};

// Laws exercising every branch with a nonzero Jacobian; in kD's configurations with L0 = 0.6
// (e ≈ 0.166 m) and L0 = 0 (e ≈ 0.766 m) every tension-only law is taut and pulling.
std::vector<NamedLaw> Laws() {
  const std::vector<ForceTablePoint> table = {{-0.2, -30.0}, {0.0, 0.0},  {0.1, 12.0},
                                              {0.3, 50.0},   {0.6, 70.0}, {0.9, 130.0}};
  return {
      {"linear, constant damping", WithConstantDamping(MakeLinearLaw(150.0), 4.0)},
      {"tension-only, constant damping", WithConstantDamping(MakeTensionOnlyLaw(150.0, 0.05), 4.0)},
      {"polynomial, proportional damping",
       WithStiffnessProportionalDamping(MakePolynomialLaw(150.0, 900.0), 0.03)},
      {"table, proportional damping",
       WithStiffnessProportionalDamping(MakePiecewiseLinearLaw(table), 0.03)},
  };
}

Vector3d Force(const ConnectionLaw& law, double l0, const Vector3d& d, const Vector3d& d_dot) {
  return CalcSpringDamper(law, l0, d, d_dot).force_on_2;
}

void ExpectJacobiansMatchFiniteDifferences(const ConnectionLaw& law, double l0, const Vector3d& d,
                                           const Vector3d& d_dot, const std::string& what) {
  const SpringDamperResult r = CalcSpringDamper(law, l0, d, d_dot);
  Matrix3d k_fd, c_fd;
  const double h = 1e-7;
  for (int j = 0; j < 3; ++j) {
    const Vector3d step = h * Vector3d::Unit(j);
    k_fd.col(j) = (Force(law, l0, d + step, d_dot) - Force(law, l0, d - step, d_dot)) / (2 * h);
    c_fd.col(j) = (Force(law, l0, d, d_dot + step) - Force(law, l0, d, d_dot - step)) / (2 * h);
  }
  EXPECT_LT((r.stiffness - k_fd).norm(), 1e-6 * r.stiffness.norm()) << what << "\n"
                                                                    << r.stiffness << "\nfd\n"
                                                                    << k_fd;
  EXPECT_LT((r.damping - c_fd).norm(), 1e-6 * r.damping.norm() + 1e-9) << what << "\n"
                                                                       << r.damping << "\nfd\n"
                                                                       << c_fd;
}

void ExpectForceIsMinusEnergyGradient(const ConnectionLaw& law, double l0, const Vector3d& d,
                                      const std::string& what) {
  const Vector3d f = Force(law, l0, d, Vector3d::Zero());
  Vector3d gradient;
  const double h = 1e-7;
  for (int j = 0; j < 3; ++j) {
    const Vector3d step = h * Vector3d::Unit(j);
    gradient[j] = (CalcSpringDamper(law, l0, d + step, Vector3d::Zero()).energy -
                   CalcSpringDamper(law, l0, d - step, Vector3d::Zero()).energy) /
                  (2 * h);
  }
  EXPECT_LT((f + gradient).norm(), 1e-6 * f.norm()) << what << "\n" << f << "\n" << -gradient;
}

TEST(SpringDamper, HandComputedValues) {
  const ConnectionLaw law = MakeLinearLaw(100.0);
  const Vector3d d(0.3, 0.4, 0.0);  // |d| = 0.5 m
  const SpringDamperResult axial = CalcSpringDamper(law, 0.4, d, Vector3d::Zero());
  EXPECT_TRUE(axial.force_on_2.isApprox(Vector3d(-6.0, -8.0, 0.0), 1e-14));  // T = 10 N
  EXPECT_DOUBLE_EQ(axial.tension, 10.0);
  EXPECT_DOUBLE_EQ(axial.energy, 0.5);
  const SpringDamperResult knot = CalcSpringDamper(law, 0.0, d, Vector3d::Zero());
  EXPECT_TRUE(knot.force_on_2.isApprox(Vector3d(-30.0, -40.0, 0.0), 1e-14));  // −k d
  EXPECT_DOUBLE_EQ(knot.tension, 50.0);
  EXPECT_DOUBLE_EQ(knot.energy, 12.5);
  EXPECT_TRUE(knot.stiffness.isApprox(-100.0 * Matrix3d::Identity(), 1e-14));
  // Compressed below its natural length, a linear spring pushes P2 away from P1.
  const SpringDamperResult pushed = CalcSpringDamper(law, 0.6, d, Vector3d::Zero());
  EXPECT_TRUE(pushed.force_on_2.isApprox(Vector3d(6.0, 8.0, 0.0), 1e-13));
}

TEST(SpringDamper, JacobiansMatchFiniteDifferencesWithNaturalLength) {
  for (const NamedLaw& l : Laws()) {
    ExpectJacobiansMatchFiniteDifferences(l.law, 0.6, kD, kDDot, l.name + ", stretched");
    ExpectJacobiansMatchFiniteDifferences(l.law, 0.6, kD, -0.2 * kDDot, l.name + ", slowing");
  }
  // Compressed (e < 0): only laws that push.
  const ConnectionLaw linear = WithConstantDamping(MakeLinearLaw(150.0), 4.0);
  ExpectJacobiansMatchFiniteDifferences(linear, 1.1, kD, kDDot, "linear, compressed");
  const ConnectionLaw poly =
      WithStiffnessProportionalDamping(MakePolynomialLaw(150.0, 900.0), 0.03);
  ExpectJacobiansMatchFiniteDifferences(poly, 1.1, kD, kDDot, "polynomial, compressed");
}

TEST(SpringDamper, JacobiansMatchFiniteDifferencesForZeroLengthLink) {
  for (const NamedLaw& l : Laws()) {
    ExpectJacobiansMatchFiniteDifferences(l.law, 0.0, kD, kDDot, l.name);
    ExpectJacobiansMatchFiniteDifferences(l.law, 0.0, 0.1 * kD, kDDot, l.name + ", short");
  }
}

TEST(SpringDamper, ForceIsMinusEnergyGradientWithoutDamping) {
  for (const NamedLaw& l : Laws()) {
    ConnectionLaw law = l.law;
    law.damping_coefficient = 0.0;
    ExpectForceIsMinusEnergyGradient(law, 0.6, kD, l.name + ", L0 > 0");
    ExpectForceIsMinusEnergyGradient(law, 0.0, kD, l.name + ", L0 = 0");
    ExpectForceIsMinusEnergyGradient(law, 0.0, 0.1 * kD, l.name + ", L0 = 0, short");
  }
}

TEST(SpringDamper, RigidRotationDissipatesNothingWithNaturalLength) {
  // ḋ = ω × d ⟂ d: ė = 0, so the damped force equals the undamped one and does no work.
  const Vector3d d_dot = kOmega.cross(kD);
  for (const NamedLaw& l : Laws()) {
    ConnectionLaw undamped = l.law;
    undamped.damping_coefficient = 0.0;
    const Vector3d f = Force(l.law, 0.6, kD, d_dot);
    EXPECT_LT((f - Force(undamped, 0.6, kD, d_dot)).norm(), 1e-12 * f.norm()) << l.name;
    EXPECT_NEAR(f.dot(d_dot), 0.0, 1e-12 * f.norm() * d_dot.norm()) << l.name;
  }
}

TEST(SpringDamper, ZeroLengthLinkDampsRelativeRotation) {
  // The seed paper's isotropic damping b δ̇: rigid rotation of the pair dissipates b |ω × d|².
  const Vector3d d_dot = kOmega.cross(kD);
  const double b = 4.0;
  const ConnectionLaw law = WithConstantDamping(MakeLinearLaw(150.0), b);
  const Vector3d f = Force(law, 0.0, kD, d_dot);
  EXPECT_NEAR(f.dot(d_dot), -b * d_dot.squaredNorm(), 1e-12 * b * d_dot.squaredNorm());
  EXPECT_TRUE((f + 150.0 * kD + b * d_dot).isZero(1e-12));
}

TEST(SpringDamper, CoincidentPointsGiveFiniteValues) {
  const ConnectionLaw law = WithConstantDamping(MakePolynomialLaw(150.0, 900.0), 4.0);
  // L0 > 0: a crushed spring; the regularised length gives zero force at d = 0, no NaN.
  for (const Vector3d& d : {Vector3d::Zero().eval(), Vector3d(1e-12, -2e-12, 0.5e-12)}) {
    const SpringDamperResult r = CalcSpringDamper(law, 0.6, d, kDDot);
    EXPECT_TRUE(r.force_on_2.allFinite() && r.stiffness.allFinite() && r.damping.allFinite());
    EXPECT_TRUE(std::isfinite(r.energy) && std::isfinite(r.tension));
    EXPECT_LE(r.force_on_2.norm(), std::abs(r.tension) + 1e-12);
  }
  EXPECT_TRUE(CalcSpringDamper(law, 0.6, Vector3d::Zero(), kDDot).force_on_2.isZero());
  // L0 = 0: the limit K(0) = dT_s/de at 0, continuous with small d.
  const SpringDamperResult at_zero = CalcSpringDamper(law, 0.0, Vector3d::Zero(), kDDot);
  EXPECT_TRUE(at_zero.force_on_2.isApprox(-4.0 * kDDot, 1e-14));
  EXPECT_TRUE(at_zero.stiffness.isApprox(-150.0 * Matrix3d::Identity(), 1e-14));
  EXPECT_TRUE(at_zero.damping.isApprox(-4.0 * Matrix3d::Identity(), 1e-14));
  const SpringDamperResult near_zero = CalcSpringDamper(law, 0.0, 1e-6 * kD, kDDot);
  EXPECT_LT((near_zero.stiffness - at_zero.stiffness).norm(), 1e-6);
  // A tension-only link with no gap also starts from its stiffness, from the taut side.
  const SpringDamperResult rope =
      CalcSpringDamper(MakeTensionOnlyLaw(150.0, 0.0), 0.0, Vector3d::Zero(), Vector3d::Zero());
  EXPECT_TRUE(rope.stiffness.isApprox(-150.0 * Matrix3d::Identity(), 1e-14));
}

TEST(SpringDamper, ZeroLengthTensionOnlyLinkIsFreeInsideItsGap) {
  const ConnectionLaw law = WithConstantDamping(MakeTensionOnlyLaw(150.0, 1.0), 4.0);
  const SpringDamperResult r = CalcSpringDamper(law, 0.0, kD, kDDot);  // |d| < g
  EXPECT_TRUE(r.force_on_2.isZero());
  EXPECT_TRUE(r.stiffness.isZero());
  EXPECT_TRUE(r.damping.isZero());
  EXPECT_EQ(r.energy, 0.0);
}

TEST(SpringDamper, InvalidInputsThrow) {
  const ConnectionLaw law = MakeLinearLaw(100.0);
  EXPECT_THROW(CalcSpringDamper(law, -0.1, kD, kDDot), InputError);
  EXPECT_THROW(CalcSpringDamper(law, std::nan(""), kD, kDDot), InputError);
  EXPECT_THROW(CalcSpringDamper(law, INFINITY, kD, kDDot), InputError);
  // A zero-length link with a pretension at zero elongation has no defined force at d = 0.
  const ConnectionLaw pretensioned = MakePiecewiseLinearLaw({{0.0, 1.0}, {0.1, 5.0}});
  EXPECT_THROW(CalcSpringDamper(pretensioned, 0.0, kD, kDDot), InputError);
  EXPECT_NO_THROW(CalcSpringDamper(pretensioned, 0.5, kD, kDDot));
  // Through the origin without a (0, 0) row: accepted.
  const ConnectionLaw through_origin = MakePiecewiseLinearLaw({{-0.3, -3.0}, {0.7, 7.0}});
  EXPECT_NO_THROW(CalcSpringDamper(through_origin, 0.0, kD, kDDot));
  EXPECT_THROW(ValidateSpringDamper(pretensioned, 0.0), InputError);
  EXPECT_THROW(ValidateSpringDamper(law, -1.0), InputError);
  EXPECT_NO_THROW(ValidateSpringDamper(pretensioned, 0.5));
  EXPECT_NO_THROW(ValidateSpringDamper(through_origin, 0.0));
}

}  // namespace
}  // namespace ancfnet
