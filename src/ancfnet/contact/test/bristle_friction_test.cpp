// The LuGre bristle in the tangent plane: at rest it holds the force σ₀ N z of its deflection;
// sliding steadily it tends to the Stribeck force N g(s) against the slip, whatever direction
// it was deflected in before; its one-axis case is FrictionLaw::StepBristle; its derivatives
// with respect to the slip velocity, the normal force and the starting deflection match central
// differences.

#include "ancfnet/contact/laws/bristle_friction.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ancfnet {
namespace {

const FrictionLaw kLaw = MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, 80.0, 0.2);

TEST(BristleFriction, AtRestHoldsTheDeflectionForce) {
  const Vector3d z0(2e-5, -1e-5, 0.0);
  for (double h : {0.0, 1e-4, 1e-2}) {
    const TangentialBristleStep s =
        CalcTangentialBristleFriction(kLaw, z0, Vector3d::Zero(), 3.0, h);
    EXPECT_LT((s.deflection - z0).norm(), 1e-18);
    EXPECT_LT((s.friction.force + 3.0 * 1e4 * z0).norm(), 1e-12);
  }
}

TEST(BristleFriction, SteadySlidingTendsToTheStribeckForceAgainstTheSlip) {
  // Deflected across the slip first: the bristle turns into the slip direction.
  const Vector3d v(0.03, 0.04, 0.0);  // s = 0.05 m/s
  Vector3d z(0.0, -4e-5, 0.0);
  TangentialBristleStep s;
  for (int i = 0; i < 200; ++i) {
    s = CalcTangentialBristleFriction(kLaw, z, v, 2.0, 1e-3);
    z = s.deflection;
  }
  const double g = kLaw.CalcStribeck(0.05);
  EXPECT_LT((z - g / 1e4 * v / 0.05).norm(), 1e-12);
  EXPECT_LT((s.friction.force + 2.0 * g * v / 0.05 + 0.2 * v).norm(), 1e-9);
}

TEST(BristleFriction, OneAxisCaseIsTheScalarStep) {
  const Vector3d axis(0.6, 0.0, 0.8);
  for (double v : {-0.02, 0.0, 3e-3}) {
    const BristleStep scalar = kLaw.StepBristle(1e-5, v, 4.0, 2e-3);
    const TangentialBristleStep vector =
        CalcTangentialBristleFriction(kLaw, 1e-5 * axis, v * axis, 4.0, 2e-3);
    EXPECT_NEAR(vector.deflection.dot(axis), scalar.deflection, 1e-18);
    EXPECT_NEAR(vector.friction.force.dot(axis), scalar.friction.force, 1e-12);
    EXPECT_NEAR(axis.dot(vector.friction.dforce_dvelocity * axis), scalar.friction.dforce_dvelocity,
                1e-9);
  }
}

TEST(BristleFriction, DerivativesMatchFiniteDifferences) {
  const double dv = 1e-9, dn = 1e-6;
  const Vector3d z0(2e-5, -3e-5, 0.0);
  for (double h : {0.0, 1e-4, 1e-2}) {
    for (const Vector3d& v :
         {Vector3d(3e-4, 2e-4, 0.0), Vector3d(4e-3, -8e-3, 0.0), Vector3d(-0.05, 0.02, 0.0)}) {
      const TangentialBristleStep s = CalcTangentialBristleFriction(kLaw, z0, v, 5.0, h);
      Matrix3d fd;
      for (int k = 0; k < 3; ++k) {
        Vector3d vp = v, vm = v;
        vp[k] += dv;
        vm[k] -= dv;
        fd.col(k) = (CalcTangentialBristleFriction(kLaw, z0, vp, 5.0, h).friction.force -
                     CalcTangentialBristleFriction(kLaw, z0, vm, 5.0, h).friction.force) /
                    (2 * dv);
      }
      EXPECT_LT((s.friction.dforce_dvelocity - fd).norm(),
                1e-6 * s.friction.dforce_dvelocity.norm())
          << "h = " << h << ", v = " << v.transpose();
      const Vector3d fd_n =
          (CalcTangentialBristleFriction(kLaw, z0, v, 5.0 + dn, h).friction.force -
           CalcTangentialBristleFriction(kLaw, z0, v, 5.0 - dn, h).friction.force) /
          (2 * dn);
      EXPECT_LT((s.friction.dforce_dnormal - fd_n).norm(), 1e-7 * fd_n.norm());
      const double dz = 1e-10;
      Matrix3d fd_z;
      for (int k = 0; k < 3; ++k) {
        Vector3d zp = z0, zm = z0;
        zp[k] += dz;
        zm[k] -= dz;
        fd_z.col(k) = (CalcTangentialBristleFriction(kLaw, zp, v, 5.0, h).friction.force -
                       CalcTangentialBristleFriction(kLaw, zm, v, 5.0, h).friction.force) /
                      (2 * dz);
      }
      EXPECT_LT((s.dforce_ddeflection * Matrix3d::Identity() - fd_z).norm(), 1e-6 * fd_z.norm())
          << "h = " << h << ", v = " << v.transpose();
    }
  }
}

TEST(BristleFriction, RefusesOtherLawsAndNegativeSteps) {
  const FrictionLaw tanh = MakeTanhFriction(0.5, 0.3, 1e-3, 1e-2);
  EXPECT_THROW(CalcTangentialBristleFriction(tanh, Vector3d::Zero(), Vector3d::Zero(), 1.0, 1e-3),
               std::logic_error);
  EXPECT_THROW(CalcTangentialBristleFriction(kLaw, Vector3d::Zero(), Vector3d::Zero(), 1.0, -1.0),
               std::logic_error);
}

}  // namespace
}  // namespace ancfnet
