#include "ancfnet/contact/distance/point_segment.hpp"

#include "ancfnet/contact/distance/direction.hpp"

namespace ancfnet {

PointSegmentDistance CalcPointSegmentDistance(const Vector3d& p, const Vector3d& a,
                                              const Vector3d& b) {
  PointSegmentDistance out;
  const Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double along = (p - a).dot(ab);
  // A segment shorter than 1e-150 m (length² underflows the quotient) is a point.
  if (!(length2 > 1e-300) || along <= 0.0) {
    out.t = 0.0;
    out.region = PointSegmentRegion::kEndA;
  } else if (along >= length2) {
    out.t = 1.0;
    out.region = PointSegmentRegion::kEndB;
  } else {
    out.t = along / length2;
    out.region = PointSegmentRegion::kInterior;
  }
  out.closest_point = a + out.t * ab;
  const Vector3d r = p - out.closest_point;
  out.distance = r.norm();
  // The fallback only where needed: it costs more than the rest of the query.
  out.direction = out.distance > 0.0 ? Vector3d(r / out.distance) : AnyUnitPerpendicular(ab);
  out.gradient << out.direction, -(1.0 - out.t) * out.direction, -out.t * out.direction;
  return out;
}

Matrix3d CalcPointSegmentHessian(const PointSegmentDistance& d, const Vector3d& a,
                                 const Vector3d& b) {
  if (!(d.distance > 0.0)) return Matrix3d::Zero();
  Matrix3d h = Matrix3d::Identity() - d.direction * d.direction.transpose();
  if (d.region == PointSegmentRegion::kInterior) {
    const Vector3d e = (b - a).normalized();
    h -= e * e.transpose();
  }
  return h / d.distance;
}

}  // namespace ancfnet
