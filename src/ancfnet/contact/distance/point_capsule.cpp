#include "ancfnet/contact/distance/point_capsule.hpp"

#include "ancfnet/contact/distance/direction.hpp"
#include "ancfnet/contact/distance/point_segment.hpp"

namespace ancfnet {

PointCapsuleDistance CalcPointCapsuleDistance(const Vector3d& p, const Vector3d& center,
                                              const Vector3d& axis, double half_length,
                                              double radius) {
  const Vector3d a = center - half_length * axis;
  const Vector3d b = center + half_length * axis;
  const PointSegmentDistance s = CalcPointSegmentDistance(p, a, b);
  PointCapsuleDistance out;
  out.distance = s.distance - radius;
  out.on_axis = !(s.distance > 1e-12 * radius);
  out.normal = out.on_axis ? AnyUnitPerpendicular(axis) : s.direction;
  out.closest_point = s.closest_point + radius * out.normal;
  out.hessian = out.on_axis ? Matrix3d::Zero() : CalcPointSegmentHessian(s, a, b);
  return out;
}

}  // namespace ancfnet
