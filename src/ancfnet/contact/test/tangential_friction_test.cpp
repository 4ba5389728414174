// The vector form of the regularised friction laws: the force opposes the slip with the scalar
// law's magnitude, and its 3×3 Jacobian matches central differences, also near zero slip.

#include "ancfnet/contact/laws/tangential_friction.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ancfnet {
namespace {

std::vector<FrictionLaw> Laws() {
  return {MakeTanhFriction(0.5, 0.3, 1e-3, 1e-2), MakeAmbrosioFriction(0.3, 1e-4, 1e-3)};
}

TEST(TangentialFriction, OpposesTheSlipWithTheScalarMagnitude) {
  for (const FrictionLaw& law : Laws()) {
    const Vector3d v(0.02, -0.05, 0.0);
    const TangentialFriction f = CalcTangentialFriction(law, v, 7.0);
    const FrictionForce scalar = law.Evaluate(v.norm(), 7.0);
    EXPECT_NEAR(f.force.norm(), std::abs(scalar.force), 1e-12);
    EXPECT_LT(f.force.dot(v), 0.0);
    EXPECT_NEAR(f.force.normalized().dot(v.normalized()), -1.0, 1e-12);
  }
}

TEST(TangentialFriction, JacobianMatchesFiniteDifferences) {
  const double h = 1e-9;
  for (const FrictionLaw& law : Laws()) {
    // Slip speeds across the regularisation and Stribeck ranges (away from the Ambrósio kinks).
    for (const Vector3d& v : {Vector3d(3e-4, 2e-4, 0.0), Vector3d(4e-3, -2e-3, 0.0),
                              Vector3d(0.05, 0.02, 0.0), Vector3d(1e-15, 0.0, 0.0)}) {
      const TangentialFriction f = CalcTangentialFriction(law, v, 5.0);
      for (int k = 0; k < 3; ++k) {
        Vector3d vp = v, vm = v;
        vp[k] += h;
        vm[k] -= h;
        const Vector3d fd = (CalcTangentialFriction(law, vp, 5.0).force -
                             CalcTangentialFriction(law, vm, 5.0).force) /
                            (2 * h);
        EXPECT_LT((f.dforce_dvelocity.col(k) - fd).norm(), 1e-6 * f.dforce_dvelocity.norm() + 1e-9)
            << "v = " << v.transpose() << ", column " << k;
      }
      const Vector3d fd_n = (CalcTangentialFriction(law, v, 5.0 + 1e-6).force -
                             CalcTangentialFriction(law, v, 5.0 - 1e-6).force) /
                            2e-6;
      EXPECT_LT((f.dforce_dnormal - fd_n).norm(), 1e-6 * (fd_n.norm() + 1e-12));
    }
  }
}

TEST(TangentialFriction, LuGreIsRefused) {
  const FrictionLaw lugre = MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, 100.0, 0.0);
  EXPECT_THROW(CalcTangentialFriction(lugre, Vector3d(1e-3, 0, 0), 1.0), std::logic_error);
}

}  // namespace
}  // namespace ancfnet
