#pragma once
/// @file Closest points of two segments (capsule–capsule and thread–thread contact), with the
/// gradient of the distance with respect to the 12 end-point coordinates.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Where on one segment its closest point lies.
enum class SegmentPart {
  kStart,     ///< parameter 0
  kInterior,  ///< parameter in (0, 1)
  kEnd,       ///< parameter 1
};

/// Closest points x_p = p0 + s (p1 − p0) and x_q = q0 + t (q1 − q0) of two segments.
struct SegmentSegmentDistance {
  double s = 0.0;         ///< closest parameter on [p0, p1], in [0, 1]
  double t = 0.0;         ///< closest parameter on [q0, q1], in [0, 1]
  Vector3d closest_p;     ///< x_p (m)
  Vector3d closest_q;     ///< x_q (m)
  double distance = 0.0;  ///< d = |x_p − x_q| (m), ≥ 0
  Vector3d direction;     ///< u = (x_p − x_q)/d, unit, from the q segment to the p segment
  Vector12d gradient;     ///< ∂d/∂[p0, p1, q0, q1] = [(1 − s) u, s u, −(1 − t) u, −t u]
  SegmentPart part_p = SegmentPart::kInterior;  ///< where s lies
  SegmentPart part_q = SegmentPart::kInterior;  ///< where t lies
  bool parallel = false;  ///< the lines are parallel (sin²θ ≤ 10⁻²⁴): the pair is one of many
};

/// Closest points of the segments [p0, p1] and [q0, q1] (m): the minimiser of the convex
/// quadratic |x_p(s) − x_q(t)|² over [0, 1]². With d1 = p1 − p0, d2 = q1 − q0, r = p0 − q0,
/// a = d1·d1, e = d2·d2, b = d1·d2, c = d1·r, f = d2·r and Δ = a e − b² (Lumelsky 1985;
/// Ericson 2005, §5.1.9):
///  1. both segments points (a, e ≤ 10⁻³⁰⁰): s = t = 0;
///  2. one a point: its parameter is 0, the other's is the clamped projection, t = clamp(f/e)
///     or s = clamp(−c/a);
///  3. otherwise s = clamp((b f − c e)/Δ) (the minimiser of the infinite lines, clamped),
///     evaluated as Δ = |d1 × d2|², b f − c e = (d1 × d2)·(d2 × r) (no cancellation for
///     nearly parallel lines); if the lines are parallel (Δ ≤ 10⁻²⁴ a e, an angle below
///     10⁻¹² rad, which costs at most about 10⁻¹² times the length in distance) s is the middle
///     of the overlap of the two segments' projections on the p line, or 0 where they do not
///     overlap;
///  4. t = (b s + f)/e, the best t for that s; if t < 0 (or > 1), t is clamped to 0 (or 1)
///     and s recomputed as the clamped best s for that t: s = clamp(−c/a) (or clamp((b − c)/a)).
/// Steps 3–4 give the exact minimiser: (s, (b s + f)/e) minimises over [0, 1] × ℝ, and when
/// that t lies outside [0, 1] the convexity of min_s over t puts the box minimiser at the
/// nearer bound (proof in docs/theory.md, "Contact distance functions").
/// Gradient: where the closest pair is unique, d is differentiable and (envelope theorem, the
/// bounds on s, t not depending on the coordinates) ∂d/∂p0 = (1 − s) u, ∂d/∂p1 = s u,
/// ∂d/∂q0 = −(1 − t) u, ∂d/∂q1 = −t u. Degenerate input: for crossing segments (d = 0) u is
/// d1 × d2 normalised, else perpendicular to the non-zero d1 or d2, else e_z (a one-sided
/// derivative of the non-smooth d). For parallel overlapping segments the gradient is that of
/// the returned (middle) pair.
SegmentSegmentDistance CalcSegmentSegmentDistance(const Vector3d& p0, const Vector3d& p1,
                                                  const Vector3d& q0, const Vector3d& q1);

/// Contact of two capsules (segments swept by spheres of radii r1, r2 ≥ 0).
struct CapsuleCapsuleDistance {
  SegmentSegmentDistance axes;  ///< closest points of the two axes
  double gap = 0.0;             ///< g = d − r1 − r2 (m), negative when they overlap
  Vector3d surface_point_p;     ///< x_p − r1 u, on the first capsule (m)
  Vector3d surface_point_q;     ///< x_q + r2 u, on the second capsule (m)
};

/// Gap g = d − r1 − r2 of the capsules of axes [p0, p1] (radius r1) and [q0, q1] (radius r2);
/// ∂g/∂[p0, p1, q0, q1] = axes.gradient. The normal pushing the first capsule away is u.
CapsuleCapsuleDistance CalcCapsuleCapsuleDistance(const Vector3d& p0, const Vector3d& p1, double r1,
                                                  const Vector3d& q0, const Vector3d& q1,
                                                  double r2);

}  // namespace ancfnet
