#pragma once
/// @file The lowest point of a function φ along a segment: the minimum over t ∈ [0, 1] of
/// φ(c(t)), c(t) = x₀ + t (x₁ − x₀), from samples and a safeguarded Newton iteration on the slope.
/// Used for the deepest point of a capsule's axis in a rigid target (contact/target_distance.hpp;
/// docs/theory.md, "Capsule chains against rigid targets").

#include <cmath>

namespace ancfnet {

/// φ and its first two derivatives along the segment at one t. With Δ = x₁ − x₀, n = ∂φ/∂x and
/// H = ∂²φ/∂x²: φ' = n·Δ and φ'' = Δᵀ H Δ.
struct SegmentSample {
  double value = 0.0;      ///< φ (m)
  double slope = 0.0;      ///< dφ/dt (m)
  double curvature = 0.0;  ///< d²φ/dt² (m)
};

/// Where the search stopped and what it cost.
struct SegmentMinimum {
  double t = 0.0;
  SegmentSample sample;  ///< at t
  int evaluations = 0;   ///< calls of `evaluate`
  double lowest_sampled_value = 0.0;  ///< the lowest φ(t_j) of step 1 below
};

/// The lowest point of φ(t) on [0, 1]; `evaluate(t)` returns the SegmentSample at t.
///  1. Samples at t_j = j/m, j = 0 … m (m = `intervals` ≥ 1); t_i the lowest (first on ties).
///  2. φ'(t_i) < 0 and i < m: the bracket [t_i, t_{i+1}]; φ'(t_i) > 0 and i > 0: [t_{i−1}, t_i];
///     otherwise t_i is the answer (an end where φ rises into the segment, or a flat sample).
///  3. In the bracket [lo, hi], φ'(lo) < 0 < φ'(hi): a Newton step t ← t − φ'/φ'' where φ'' > 0
///     and it lands inside (lo, hi), else bisection; lo or hi moves to t by the sign of φ'(t).
///     Stops when |φ'| ≤ `slope_tolerance`, the bracket is narrower than 10⁻¹⁴ or after 64 steps.
/// Returns the last point of step 3, or t_i where that is higher (near the minimum φ is flat to
/// rounding, so the iterate, not the lowest value, is the accurate t*). For a convex φ (a convex
/// target) φ' increases along t, so m = 1 finds the global minimum; for a non-convex φ (a mesh)
/// it finds a local minimum no higher than the lowest sample, and misses minima that are not
/// next to it.
template <class Evaluate>
SegmentMinimum FindSegmentMinimum(const Evaluate& evaluate, int intervals, double slope_tolerance) {
  SegmentMinimum best;
  int lowest = 0;
  best.sample = evaluate(0.0);
  best.evaluations = 1;
  for (int j = 1; j <= intervals; ++j) {
    const SegmentSample s = evaluate(static_cast<double>(j) / intervals);
    ++best.evaluations;
    if (s.value < best.sample.value) lowest = j, best.sample = s;
  }
  best.t = static_cast<double>(lowest) / intervals;
  best.lowest_sampled_value = best.sample.value;
  const SegmentSample at_lowest = best.sample;
  double lo, hi;
  if (at_lowest.slope < 0.0 && lowest < intervals) {
    lo = best.t;
    hi = static_cast<double>(lowest + 1) / intervals;
  } else if (at_lowest.slope > 0.0 && lowest > 0) {
    lo = static_cast<double>(lowest - 1) / intervals;
    hi = best.t;
  } else {
    return best;
  }
  double t = best.t;
  SegmentSample s = at_lowest;
  for (int k = 0; k < 64 && std::abs(s.slope) > slope_tolerance && hi - lo > 1e-14; ++k) {
    double next = 0.5 * (lo + hi);
    if (s.curvature > 0.0) {
      const double newton = t - s.slope / s.curvature;
      if (newton > lo && newton < hi) next = newton;
    }
    t = next;
    s = evaluate(t);
    ++best.evaluations;
    (s.slope < 0.0 ? lo : hi) = t;
  }
  if (s.value <= at_lowest.value) {
    best.t = t;
    best.sample = s;
  }
  return best;
}

}  // namespace ancfnet
