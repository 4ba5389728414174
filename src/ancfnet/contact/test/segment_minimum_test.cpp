// FindSegmentMinimum on functions of t with known minima: a convex parabola (Newton converges in
// a few steps), monotone functions (an end), and a double well whose deeper minimum lies next to
// the deepest of five samples.

#include "ancfnet/contact/distance/segment_minimum.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ancfnet {
namespace {

TEST(SegmentMinimum, ConvexParabolaInFewSteps) {
  // φ = (t − 0.3)² + 1 + 0.1 t⁴: φ' = 2 (t − 0.3) + 0.4 t³ = 0 at t = 0.2907… (by bisection here).
  const auto f = [](double t) {
    return SegmentSample{.value = (t - 0.3) * (t - 0.3) + 1.0 + 0.1 * t * t * t * t,
                         .slope = 2.0 * (t - 0.3) + 0.4 * t * t * t,
                         .curvature = 2.0 + 1.2 * t * t};
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)).slope < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const SegmentMinimum m = FindSegmentMinimum(f, 1, 1e-14);
  EXPECT_NEAR(m.t, lo, 1e-13);
  EXPECT_LE(m.evaluations, 8);
}

TEST(SegmentMinimum, MonotoneFunctionsStopAtAnEnd) {
  const auto rising = [](double t) { return SegmentSample{.value = t, .slope = 1.0}; };
  const auto falling = [](double t) { return SegmentSample{.value = -t, .slope = -1.0}; };
  EXPECT_EQ(FindSegmentMinimum(rising, 1, 1e-12).t, 0.0);
  EXPECT_EQ(FindSegmentMinimum(falling, 1, 1e-12).t, 1.0);
  EXPECT_EQ(FindSegmentMinimum(falling, 4, 1e-12).evaluations, 5);
}

TEST(SegmentMinimum, DoubleWellFindsTheDeeperWellNextToTheDeepestSample) {
  // φ = −exp(−((t − 0.2)/0.1)²) − 1.5 exp(−((t − 0.8)/0.1)²): wells at 0.2 and (deeper) ≈ 0.8.
  const auto f = [](double t) {
    SegmentSample s;
    for (const auto& [c, a] : {std::pair{0.2, 1.0}, std::pair{0.8, 1.5}}) {
      const double u = (t - c) / 0.1, g = a * std::exp(-u * u);
      s.value -= g;
      s.slope += 2.0 * u / 0.1 * g;
      s.curvature += (2.0 - 4.0 * u * u) / 0.01 * g;
    }
    return s;
  };
  // The deeper minimum by a dense scan, refined by bisection on the slope.
  double lo = 0.7, hi = 0.9;
  for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)).slope < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const SegmentMinimum m = FindSegmentMinimum(f, 4, 1e-12);
  EXPECT_NEAR(m.t, lo, 1e-10);
  EXPECT_NEAR(m.sample.value, f(lo).value, 1e-14);
  // With one interval (both ends shallow) it still returns a local minimum below both ends.
  const SegmentMinimum coarse = FindSegmentMinimum(f, 1, 1e-12);
  EXPECT_LT(coarse.sample.value, std::min(f(0.0).value, f(1.0).value) - 0.5);
  EXPECT_LT(std::abs(coarse.sample.slope), 1e-9);
}

}  // namespace
}  // namespace ancfnet
