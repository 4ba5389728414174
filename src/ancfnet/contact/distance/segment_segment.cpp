#include "ancfnet/contact/distance/segment_segment.hpp"

#include <algorithm>

#include "ancfnet/contact/distance/direction.hpp"

namespace ancfnet {
namespace {

constexpr double kZeroLength2 = 1e-300;
constexpr double kParallelSin2 = 1e-24;

double Clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

SegmentPart PartOf(double x) {
  if (x <= 0.0) return SegmentPart::kStart;
  if (x >= 1.0) return SegmentPart::kEnd;
  return SegmentPart::kInterior;
}

}  // namespace

SegmentSegmentDistance CalcSegmentSegmentDistance(const Vector3d& p0, const Vector3d& p1,
                                                  const Vector3d& q0, const Vector3d& q1) {
  SegmentSegmentDistance out;
  const Vector3d d1 = p1 - p0;
  const Vector3d d2 = q1 - q0;
  const Vector3d r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  double s = 0.0;
  double t = 0.0;
  if (a <= kZeroLength2 && e <= kZeroLength2) {
    // Two points.
  } else if (a <= kZeroLength2) {
    t = Clamp01(f / e);
  } else if (e <= kZeroLength2) {
    s = Clamp01(-d1.dot(r) / a);
  } else {
    const double b = d1.dot(d2);
    const double c = d1.dot(r);
    // Δ = a e − b² = |d1 × d2|² and b f − c e = (d1 × d2)·(d2 × r), from the cross products
    // to avoid the cancellation of the dot-product form for nearly parallel segments.
    const Vector3d n = d1.cross(d2);
    const double denom = n.squaredNorm();
    if (denom > kParallelSin2 * a * e) {
      s = Clamp01(n.dot(d2.cross(r)) / denom);
    } else {
      out.parallel = true;
      // Parameters of q0 and q1 projected on the p line; the middle of the overlap with [0, 1].
      const double s_q0 = -c / a;
      const double s_q1 = (b - c) / a;
      const double lo = std::max(0.0, std::min(s_q0, s_q1));
      const double hi = std::min(1.0, std::max(s_q0, s_q1));
      s = lo <= hi ? 0.5 * (lo + hi) : 0.0;
    }
    t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0;
      s = Clamp01(-c / a);
    } else if (t > 1.0) {
      t = 1.0;
      s = Clamp01((b - c) / a);
    }
  }
  out.s = s;
  out.t = t;
  out.part_p = PartOf(s);
  out.part_q = PartOf(t);
  out.closest_p = p0 + s * d1;
  out.closest_q = q0 + t * d2;
  const Vector3d w = out.closest_p - out.closest_q;
  out.distance = w.norm();
  if (out.distance > 0.0) {
    out.direction = w / out.distance;
  } else {
    const Vector3d axis = a > kZeroLength2 ? d1 : d2;
    out.direction = NormalizedOr(d1.cross(d2), AnyUnitPerpendicular(axis));
  }
  const Vector3d& u = out.direction;
  out.gradient << (1.0 - s) * u, s * u, -(1.0 - t) * u, -t * u;
  return out;
}

CapsuleCapsuleDistance CalcCapsuleCapsuleDistance(const Vector3d& p0, const Vector3d& p1, double r1,
                                                  const Vector3d& q0, const Vector3d& q1,
                                                  double r2) {
  CapsuleCapsuleDistance out;
  out.axes = CalcSegmentSegmentDistance(p0, p1, q0, q1);
  out.gap = out.axes.distance - r1 - r2;
  out.surface_point_p = out.axes.closest_p - r1 * out.axes.direction;
  out.surface_point_q = out.axes.closest_q + r2 * out.axes.direction;
  return out;
}

}  // namespace ancfnet
