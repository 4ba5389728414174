#include "ancfnet/elements/rope_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ancfnet {
namespace {

constexpr double kSmoothing = 1e-3;

// ψ′ = φ and φ′, φ″ are its derivatives: central differences across the band and far from it.
TEST(RopeLaw, DerivativesMatchFiniteDifferences) {
  for (double eps = -0.3; eps <= 0.05; eps += eps < -0.01 || eps > 0.01 ? 0.013 : 1.7e-4) {
    const double h = 1e-7 * std::max(std::abs(eps), kSmoothing);
    const RopeLawValue law = CalcSmoothRopeLaw(eps, kSmoothing);
    const RopeLawValue up = CalcSmoothRopeLaw(eps + h, kSmoothing);
    const RopeLawValue down = CalcSmoothRopeLaw(eps - h, kSmoothing);
    EXPECT_NEAR((up.energy - down.energy) / (2 * h), law.force, 1e-7 * (law.force + kSmoothing))
        << "ε = " << eps;
    EXPECT_NEAR((up.force - down.force) / (2 * h), law.slope, 1e-6) << "ε = " << eps;
    EXPECT_NEAR((up.slope - down.slope) / (2 * h), law.curvature, 1e-6 * (1 + law.curvature))
        << "ε = " << eps;
  }
}

// The energy is measured from the least Green strain ε = −½ (a material line shrunk to a point),
// so it is never negative: measured from ε = 0 (as before), a slack thread had ψ < 0 and a free
// net's strain energy went negative (issue 17).
TEST(RopeLaw, EnergyIsNeverNegativeAndFarFromTheBandTheLawIsExact) {
  EXPECT_EQ(CalcSmoothRopeLaw(-0.5, kSmoothing).energy, 0.0);
  double previous = 0.0;
  for (double eps = -0.5; eps <= 0.02; eps += 1e-4) {
    const double energy = CalcSmoothRopeLaw(eps, kSmoothing).energy;
    EXPECT_GE(energy, previous) << "ε = " << eps;  // ψ′ = φ > 0: increasing, hence ≥ ψ(−½) = 0
    previous = energy;
  }
  EXPECT_DOUBLE_EQ(CalcSmoothRopeLaw(0.0, kSmoothing).force, kSmoothing / 2);
  // Away from the band φ − max(ε, 0) = ε_s²/(4|ε|) to leading order.
  const double tail = kSmoothing * kSmoothing / 0.4;
  EXPECT_NEAR(CalcSmoothRopeLaw(0.1, kSmoothing).force, 0.1 + tail, 1e-4 * tail);
  EXPECT_NEAR(CalcSmoothRopeLaw(-0.1, kSmoothing).force, tail, 1e-4 * tail);
  // Stretched far beyond ε_s, the energy grows like the linear law's ½ ε².
  const double e1 = CalcSmoothRopeLaw(0.1, kSmoothing).energy;
  const double e2 = CalcSmoothRopeLaw(0.2, kSmoothing).energy;
  EXPECT_NEAR(e2 - e1, 0.5 * (0.2 * 0.2 - 0.1 * 0.1), 1e-3 * kSmoothing);
}

}  // namespace
}  // namespace ancfnet
