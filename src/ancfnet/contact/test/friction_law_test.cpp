#include "ancfnet/contact/laws/friction_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

void ExpectNearRelative(double analytic, double fd, const std::string& what) {
  EXPECT_NEAR(analytic, fd, 1e-6 * (std::abs(analytic) + std::abs(fd)) + 1e-10) << what;
}

void ExpectRegularisedDerivativesMatch(const FrictionLaw& law, double v, double normal) {
  const FrictionForce f = law.Evaluate(v, normal);
  const double hv = 1e-7 * std::max(std::abs(v), 1e-3);
  const double hn = 1e-6 * normal;
  const std::string where =
      "kind " + std::to_string(static_cast<int>(law.kind)) + " v " + std::to_string(v);
  ExpectNearRelative(
      f.dforce_dvelocity,
      (law.Evaluate(v + hv, normal).force - law.Evaluate(v - hv, normal).force) / (2 * hv),
      "dF/dv " + where);
  ExpectNearRelative(
      f.dforce_dnormal,
      (law.Evaluate(v, normal + hn).force - law.Evaluate(v, normal - hn).force) / (2 * hn),
      "dF/dN " + where);
}

TEST(FrictionLaw, RegularisedDerivativesMatchFiniteDifferences) {
  const FrictionLaw ambrosio = MakeAmbrosioFriction(0.4, 1e-4, 1e-3);
  const FrictionLaw tanh_law = MakeTanhFriction(0.5, 0.3, 1e-3, 1e-2);
  // Away from the kinks of Ambrósio's ramp (at v0 and v1).
  for (double v : {-0.5, -5e-4, -5e-5, 3e-4, 7e-4, 2e-3, 0.2}) {
    ExpectRegularisedDerivativesMatch(ambrosio, v, 12.0);
    ExpectRegularisedDerivativesMatch(tanh_law, v, 12.0);
  }
  ExpectRegularisedDerivativesMatch(tanh_law, 0.0, 12.0);
}

TEST(FrictionLaw, RegularisedValues) {
  const FrictionLaw ambrosio = MakeAmbrosioFriction(0.4, 1e-4, 1e-3);
  EXPECT_EQ(ambrosio.Evaluate(5e-5, 10.0).force, 0.0);                         // c_d = 0 below v0
  EXPECT_NEAR(ambrosio.Evaluate(5.5e-4, 10.0).force, -0.4 * 10 * 0.5, 1e-12);  // half-way
  EXPECT_DOUBLE_EQ(ambrosio.Evaluate(-0.1, 10.0).force, 4.0);                  // opposes v
  EXPECT_EQ(ambrosio.Evaluate(0.1, 0.0).force, 0.0);                           // no normal force
  const FrictionLaw tanh_law = MakeTanhFriction(0.5, 0.3, 1e-3, 1e-2);
  EXPECT_NEAR(tanh_law.Evaluate(1.0, 10.0).force, -3.0, 1e-12);  // μ_k when fast
  EXPECT_NEAR(tanh_law.CalcStribeck(0.0), 0.5, 1e-15);           // μ_s at rest
  EXPECT_EQ(tanh_law.Evaluate(0.0, 10.0).force, 0.0);
}

TEST(FrictionLaw, BristleStepDerivativesMatchFiniteDifferences) {
  const FrictionLaw law = MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, 40.0, 0.7);
  for (double h : {1e-5, 1e-3}) {
    for (double z0 : {-3e-5, 0.0, 2e-5}) {
      for (double v : {-0.3, -4e-3, 1e-3, 0.05}) {
        const BristleStep s = law.StepBristle(z0, v, 8.0, h);
        const double hv = 1e-6 * std::abs(v);
        const double fd_v = (law.StepBristle(z0, v + hv, 8.0, h).friction.force -
                             law.StepBristle(z0, v - hv, 8.0, h).friction.force) /
                            (2 * hv);
        const double fd_n = (law.StepBristle(z0, v, 8.0 + 1e-5, h).friction.force -
                             law.StepBristle(z0, v, 8.0 - 1e-5, h).friction.force) /
                            2e-5;
        const std::string where =
            "h " + std::to_string(h) + " z0 " + std::to_string(z0) + " v " + std::to_string(v);
        ExpectNearRelative(s.friction.dforce_dvelocity, fd_v, "dF/dv " + where);
        ExpectNearRelative(s.friction.dforce_dnormal, fd_n, "dF/dN " + where);
        // The step satisfies its implicit-Euler equation.
        const double g = law.CalcStribeck(std::abs(v));
        EXPECT_NEAR((s.deflection - z0) / h,
                    v - law.bristle_stiffness * std::abs(v) * s.deflection / g, 1e-9 * std::abs(v));
      }
    }
  }
}

TEST(FrictionLaw, BristleSaturatesAtTheStribeckCurve) {
  // Sliding steadily, z → g(|v|)/σ0 sign(v) and F_t → −N g(|v|) − σ2 v.
  const FrictionLaw law = MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, 40.0, 0.0);
  double z = 0.0;
  BristleStep s;
  for (int i = 0; i < 1000; ++i) {
    s = law.StepBristle(z, 0.02, 10.0, 1e-3);
    z = s.deflection;
  }
  EXPECT_NEAR(z, law.CalcStribeck(0.02) / 1e4, 1e-12);
  EXPECT_NEAR(s.friction.force, -10.0 * law.CalcStribeck(0.02), 1e-9);
}

TEST(FrictionLaw, InvalidParametersThrow) {
  EXPECT_THROW(MakeAmbrosioFriction(-0.1, 1e-4, 1e-3), InputError);
  EXPECT_THROW(MakeAmbrosioFriction(0.3, 1e-3, 1e-3), InputError);
  EXPECT_THROW(MakeTanhFriction(0.2, 0.3, 1e-3, 1e-2), InputError);  // μ_s < μ_k
  EXPECT_THROW(MakeTanhFriction(0.5, 0.3, 0.0, 1e-2), InputError);
  EXPECT_THROW(MakeLuGreFriction(0.5, 0.0, 1e-2, 1e4, 0, 0), InputError);
  EXPECT_THROW(MakeLuGreFriction(0.5, 0.3, 1e-2, 0.0, 0, 0), InputError);
  EXPECT_THROW(MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, -1, 0), InputError);
  const FrictionLaw lugre = MakeLuGreFriction(0.5, 0.3, 1e-2, 1e4, 0, 0);
  EXPECT_THROW(lugre.Evaluate(0.1, 1.0), std::logic_error);
  EXPECT_THROW(lugre.StepBristle(0.0, 0.1, 1.0, 0.0), std::logic_error);
  EXPECT_THROW(MakeTanhFriction(0.5, 0.3, 1e-3, 1e-2).StepBristle(0, 0.1, 1, 1e-3),
               std::logic_error);
}

}  // namespace
}  // namespace ancfnet
