#include "ancfnet/elements/connection_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// A measured-looking table, not through the origin at its first row, with unequal segments.
std::vector<ForceTablePoint> Table() {
  return {{-0.01, -2.0}, {0.0, 0.0}, {0.01, 1.0}, {0.03, 5.0}};
}

// ∫ₐᵇ f by the composite trapezoid rule on n intervals: independent of the closed forms, and
// accurate to O(h²) even across the kinks of piecewise laws.
double Quadrature(const std::function<double(double)>& f, double a, double b, int n = 200000) {
  const double h = (b - a) / n;
  double sum = 0.5 * (f(a) + f(b));
  for (int i = 1; i < n; ++i) sum += f(a + i * h);
  return sum * h;
}

// |analytic − finite difference| within 1e-6 relative (plus a floor for zero derivatives).
void ExpectNearRelative(double analytic, double fd, const std::string& what) {
  EXPECT_NEAR(analytic, fd, 1e-6 * std::abs(analytic) + 1e-9) << what;
}

// Every derivative the law returns, against central differences, at (e, ė).
void ExpectDerivativesMatchFiniteDifferences(const ConnectionLaw& law, double e, double e_dot) {
  const double h = 1e-7;
  const std::string where = "at e = " + std::to_string(e) + ", e_dot = " + std::to_string(e_dot);
  const ConnectionForce t = law.Evaluate(e, e_dot);
  ExpectNearRelative(
      t.dforce_de, (law.Evaluate(e + h, e_dot).force - law.Evaluate(e - h, e_dot).force) / (2 * h),
      "dT/de " + where);
  ExpectNearRelative(
      t.dforce_dedot,
      (law.Evaluate(e, e_dot + h).force - law.Evaluate(e, e_dot - h).force) / (2 * h),
      "dT/de_dot " + where);
  const SpringTerms s = law.CalcSpring(e);
  ExpectNearRelative(s.stiffness,
                     (law.CalcSpring(e + h).force - law.CalcSpring(e - h).force) / (2 * h),
                     "dT_s/de " + where);
  ExpectNearRelative(s.curvature,
                     (law.CalcSpring(e + h).stiffness - law.CalcSpring(e - h).stiffness) / (2 * h),
                     "d2T_s/de2 " + where);
  ExpectNearRelative(
      law.CalcDamping(e).dcoefficient_de,
      (law.CalcDamping(e + h).coefficient - law.CalcDamping(e - h).coefficient) / (2 * h),
      "db/de " + where);
}

TEST(ConnectionLaw, LinearValues) {
  const ConnectionLaw law = WithConstantDamping(MakeLinearLaw(200.0), 3.0);
  const ConnectionForce t = law.Evaluate(0.03, 0.5);
  EXPECT_DOUBLE_EQ(t.force, 200.0 * 0.03 + 3.0 * 0.5);
  EXPECT_DOUBLE_EQ(t.dforce_de, 200.0);
  EXPECT_DOUBLE_EQ(t.dforce_dedot, 3.0);
  EXPECT_DOUBLE_EQ(law.Evaluate(-0.02, 0.0).force, -4.0);  // a linear law also pushes
  EXPECT_DOUBLE_EQ(law.CalcEnergy(0.03), 0.5 * 200.0 * 0.03 * 0.03);
}

TEST(ConnectionLaw, PolynomialValues) {
  const ConnectionLaw law = MakePolynomialLaw(100.0, 1.0e5);
  const SpringTerms s = law.CalcSpring(0.02);
  EXPECT_DOUBLE_EQ(s.force, 100.0 * 0.02 + 1.0e5 * 8.0e-6);  // 2.8 N
  EXPECT_DOUBLE_EQ(s.stiffness, 100.0 + 3.0e5 * 4.0e-4);     // 220 N/m
  EXPECT_DOUBLE_EQ(s.curvature, 6.0e5 * 0.02);               // 12000 N/m²
  EXPECT_DOUBLE_EQ(law.CalcSpring(-0.02).force, -2.8);       // odd in e
  EXPECT_DOUBLE_EQ(law.CalcEnergy(0.02), 0.5 * 100.0 * 4.0e-4 + 0.25 * 1.0e5 * 1.6e-7);
}

TEST(ConnectionLaw, TensionOnlyTransmitsNoCompressionAndNothingInTheGap) {
  const ConnectionLaw law = WithConstantDamping(MakeTensionOnlyLaw(100.0, 0.01), 5.0);
  for (double e : {-0.05, -0.001, 0.0, 0.005, 0.01}) {
    for (double e_dot : {-2.0, 0.0, 2.0}) {
      const ConnectionForce t = law.Evaluate(e, e_dot);
      EXPECT_EQ(t.force, 0.0) << e << " " << e_dot;
      EXPECT_EQ(t.dforce_de, 0.0);
      EXPECT_EQ(t.dforce_dedot, 0.0);
    }
    EXPECT_EQ(law.CalcEnergy(e), 0.0);
  }
  const ConnectionForce taut = law.Evaluate(0.03, 0.1);
  EXPECT_DOUBLE_EQ(taut.force, 100.0 * 0.02 + 5.0 * 0.1);
  EXPECT_DOUBLE_EQ(taut.dforce_de, 100.0);
  EXPECT_DOUBLE_EQ(taut.dforce_dedot, 5.0);
  // Taut but shortening fast: the damper would push; a thread cannot.
  const ConnectionForce shortening = law.Evaluate(0.03, -1.0);
  EXPECT_EQ(shortening.force, 0.0);
  EXPECT_EQ(shortening.dforce_de, 0.0);
  EXPECT_EQ(shortening.dforce_dedot, 0.0);
  EXPECT_DOUBLE_EQ(law.CalcEnergy(0.03), 0.5 * 100.0 * 0.02 * 0.02);
}

TEST(ConnectionLaw, PiecewiseLinearReproducesItsTableAndInterpolatesLinearly) {
  const ConnectionLaw law = MakePiecewiseLinearLaw(Table());
  for (const ForceTablePoint& point : Table())
    EXPECT_EQ(law.CalcSpring(point.elongation).force, point.force) << point.elongation;
  const std::vector<ForceTablePoint> table = Table();
  for (std::size_t i = 0; i + 1 < table.size(); ++i) {
    const ForceTablePoint& a = table[i];
    const ForceTablePoint& b = table[i + 1];
    const double slope = (b.force - a.force) / (b.elongation - a.elongation);
    for (double t : {0.25, 0.5, 0.9}) {
      const double e = a.elongation + t * (b.elongation - a.elongation);
      EXPECT_NEAR(law.CalcSpring(e).force, a.force + t * (b.force - a.force), 1e-12);
      EXPECT_NEAR(law.CalcSpring(e).stiffness, slope, 1e-9 * std::abs(slope));
    }
  }
  // Linear extrapolation with the end segments' slopes: 200 N/m below, 200 N/m above.
  EXPECT_NEAR(law.CalcSpring(-0.02).force, -4.0, 1e-12);
  EXPECT_NEAR(law.CalcSpring(0.05).force, 9.0, 1e-12);
  EXPECT_NEAR(law.CalcSpring(0.05).stiffness, 200.0, 1e-9);
  // At a table point the slope is that of the segment to its right.
  EXPECT_NEAR(law.CalcSpring(0.0).stiffness, 100.0, 1e-9);
}

TEST(ConnectionLaw, EnergyIsTheIntegralOfTheSpringForce) {
  std::vector<ConnectionLaw> laws = {
      MakeLinearLaw(200.0), MakeTensionOnlyLaw(100.0, 0.01), MakePolynomialLaw(100.0, 1.0e5),
      MakePiecewiseLinearLaw(Table()),
      // Not through the origin (a pretension of 5/6 N at e = 0) and non-monotonic.
      MakePiecewiseLinearLaw({{-0.02, -1.5}, {0.01, 2.0}, {0.02, 1.0}, {0.04, 3.0}})};
  for (std::size_t k = 0; k < laws.size(); ++k) {
    const ConnectionLaw& law = laws[k];
    for (double e : {-0.035, -0.015, -0.004, 0.0, 0.007, 0.015, 0.025, 0.06}) {
      const double quadrature =
          Quadrature([&](double s) { return law.CalcSpring(s).force; }, 0.0, e);
      EXPECT_NEAR(law.CalcEnergy(e), quadrature, 1e-9 * (std::abs(quadrature) + 1e-6))
          << "law " << k << ", e = " << e;
    }
  }
}

TEST(ConnectionLaw, DerivativesMatchFiniteDifferences) {
  const std::vector<ConnectionLaw> springs = {MakeLinearLaw(200.0), MakeTensionOnlyLaw(100.0, 0.01),
                                              MakePolynomialLaw(100.0, 1.0e5),
                                              MakePiecewiseLinearLaw(Table())};
  for (const ConnectionLaw& spring : springs) {
    for (const ConnectionLaw& law : {spring, WithConstantDamping(spring, 3.0),
                                     WithStiffnessProportionalDamping(spring, 0.02)}) {
      // Away from the kinks (e = g, table points); tension-only laws taut and pulling.
      for (double e : {-0.025, -0.004, 0.015, 0.022, 0.045}) {
        if (spring.spring == SpringKind::kTensionOnly && e <= spring.gap) continue;
        for (double e_dot : {-0.3, 0.0, 0.7})
          ExpectDerivativesMatchFiniteDifferences(law, e, e_dot);
      }
    }
  }
}

TEST(ConnectionLaw, StiffnessProportionalDamping) {
  const ConnectionLaw law = WithStiffnessProportionalDamping(MakePolynomialLaw(100.0, 1.0e5), 0.02);
  const ConnectionForce t = law.Evaluate(0.02, 0.5);
  EXPECT_DOUBLE_EQ(t.dforce_dedot, 0.02 * 220.0);
  EXPECT_DOUBLE_EQ(t.force, 2.8 + 0.02 * 220.0 * 0.5);
  EXPECT_DOUBLE_EQ(t.dforce_de, 220.0 + 0.02 * 12000.0 * 0.5);
  // A falling segment of a table has negative stiffness; its damping is zero, never negative.
  const ConnectionLaw falling = WithStiffnessProportionalDamping(
      MakePiecewiseLinearLaw({{0.0, 0.0}, {0.01, 2.0}, {0.02, 1.0}}), 0.02);
  EXPECT_EQ(falling.CalcDamping(0.015).coefficient, 0.0);
  EXPECT_DOUBLE_EQ(falling.CalcDamping(0.005).coefficient, 0.02 * 200.0);
}

TEST(ConnectionLaw, InvalidInputsThrow) {
  const double nan = std::nan("");
  EXPECT_THROW(MakeLinearLaw(0.0), InputError);
  EXPECT_THROW(MakeLinearLaw(-1.0), InputError);
  EXPECT_THROW(MakeLinearLaw(nan), InputError);
  EXPECT_THROW(MakeLinearLaw(INFINITY), InputError);
  EXPECT_THROW(MakeTensionOnlyLaw(0.0, 0.0), InputError);
  EXPECT_THROW(MakeTensionOnlyLaw(10.0, -0.01), InputError);
  EXPECT_THROW(MakePolynomialLaw(-1.0, 1.0), InputError);
  EXPECT_THROW(MakePolynomialLaw(10.0, -1.0), InputError);  // softening: negative stiffness
  EXPECT_THROW(MakePiecewiseLinearLaw({}), InputError);
  EXPECT_THROW(MakePiecewiseLinearLaw({{0.0, 0.0}}), InputError);
  EXPECT_THROW(MakePiecewiseLinearLaw({{0.0, 0.0}, {0.0, 1.0}}), InputError);
  EXPECT_THROW(MakePiecewiseLinearLaw({{0.0, 0.0}, {0.02, 1.0}, {0.01, 2.0}}), InputError);
  EXPECT_THROW(MakePiecewiseLinearLaw({{0.0, 0.0}, {0.01, nan}}), InputError);
  EXPECT_THROW(WithConstantDamping(MakeLinearLaw(1.0), -0.1), InputError);
  EXPECT_THROW(WithStiffnessProportionalDamping(MakeLinearLaw(1.0), -0.1), InputError);
  EXPECT_THROW(WithStiffnessProportionalDamping(MakeLinearLaw(1.0), nan), InputError);
  // Allowed: zero gap, zero k3, zero damping, a non-monotonic force, a table without (0, 0).
  EXPECT_NO_THROW(MakeTensionOnlyLaw(10.0, 0.0));
  EXPECT_NO_THROW(MakePolynomialLaw(10.0, 0.0));
  EXPECT_NO_THROW(WithConstantDamping(MakeLinearLaw(1.0), 0.0));
  EXPECT_NO_THROW(MakePiecewiseLinearLaw({{0.01, 1.0}, {0.02, 3.0}, {0.03, 2.0}}));
  // A law filled by hand is checked by ValidateConnectionLaw.
  ConnectionLaw by_hand;
  by_hand.spring = SpringKind::kPiecewiseLinear;
  EXPECT_THROW(ValidateConnectionLaw(by_hand), InputError);
  by_hand = MakeLinearLaw(1.0);
  by_hand.damping_coefficient = -1.0;
  EXPECT_THROW(ValidateConnectionLaw(by_hand), InputError);
}

TEST(ConnectionLaw, ErrorMessagesNameTheParameter) {
  try {
    MakePiecewiseLinearLaw({{0.0, 0.0}, {0.02, 1.0}, {0.01, 2.0}});
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("increase strictly (row 3"), std::string::npos)
        << error.what();
  }
  try {
    MakePolynomialLaw(10.0, -1.0);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("k3"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ancfnet
