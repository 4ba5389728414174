#include "ancfnet/contact/target_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ancfnet/contact/distance/point_box.hpp"
#include "ancfnet/contact/distance/point_capsule.hpp"
#include "ancfnet/contact/distance/point_cylinder.hpp"
#include "ancfnet/contact/distance/point_plane.hpp"
#include "ancfnet/contact/distance/point_sphere.hpp"
#include "ancfnet/contact/distance/segment_minimum.hpp"

namespace ancfnet {

TargetDistance CalcPointTargetDistance(const ContactTarget& t, const Vector3d& x) {
  switch (t.kind) {
    case ContactTarget::Kind::kPlane: {
      const PointPlaneDistance d = CalcPointPlaneDistance(x, t.point, t.normal);
      return {d.distance, d.gradient_p, Matrix3d::Zero()};
    }
    case ContactTarget::Kind::kSphere: {
      const PointSphereDistance d = CalcPointSphereDistance(x, t.point, t.radius);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kBox: {
      const PointBoxDistance d = CalcPointBoxDistance(x, t.point, t.half_extents, t.rotation);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kCylinder: {
      const PointCylinderDistance d =
          CalcPointCylinderDistance(x, t.point, t.normal, t.radius, t.half_length);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kCapsule: {
      const PointCapsuleDistance d =
          CalcPointCapsuleDistance(x, t.point, t.normal, t.half_length, t.radius);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kMesh: {
      const MeshDistance d = t.mesh->CalcDistance(x);
      return {d.distance, d.normal, d.hessian};
    }
  }
  return {};
}

TargetBoundingSphere CalcTargetBoundingSphere(const ContactTarget& t) {
  switch (t.kind) {
    case ContactTarget::Kind::kPlane:
      return {t.point, std::numeric_limits<double>::infinity()};
    case ContactTarget::Kind::kSphere:
      return {t.point, t.radius};
    case ContactTarget::Kind::kBox:
      return {t.point, t.half_extents.norm()};
    case ContactTarget::Kind::kCylinder:
      return {t.point, std::hypot(t.half_length, t.radius)};
    case ContactTarget::Kind::kCapsule:
      return {t.point, t.half_length + t.radius};
    case ContactTarget::Kind::kMesh: {
      const Eigen::Matrix3Xd& vertices = t.mesh->mesh().vertices;
      const Vector3d center = 0.5 * (vertices.rowwise().minCoeff() + vertices.rowwise().maxCoeff());
      return {center, (vertices.colwise() - center).colwise().norm().maxCoeff()};
    }
  }
  return {t.point, std::numeric_limits<double>::infinity()};
}

SegmentTargetDistance CalcSegmentTargetDistance(const ContactTarget& target, const Vector3d& x0,
                                                const Vector3d& x1) {
  const Vector3d delta = x1 - x0;
  SegmentTargetDistance r;
  double sampled_bound = std::numeric_limits<double>::infinity();
  if (delta.squaredNorm() > 0.0) {
    const auto evaluate = [&](double t) {
      const TargetDistance d = CalcPointTargetDistance(target, x0 + t * delta);
      return SegmentSample{.value = d.distance,
                           .slope = d.normal.dot(delta),
                           .curvature = delta.dot(d.hessian * delta)};
    };
    const int intervals = target.kind == ContactTarget::Kind::kMesh ? 4 : 1;
    const SegmentMinimum m = FindSegmentMinimum(evaluate, intervals, 1e-12 * delta.norm());
    r.t = m.t;
    r.evaluations = m.evaluations + 1;
    if (intervals > 1) sampled_bound = m.lowest_sampled_value - delta.norm() / (2.0 * intervals);
  }
  static_cast<TargetDistance&>(r) = CalcPointTargetDistance(target, x0 + r.t * delta);
  r.lower_bound = std::min(r.distance, sampled_bound);
  return r;
}

}  // namespace ancfnet
