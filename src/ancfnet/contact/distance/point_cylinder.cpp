#include "ancfnet/contact/distance/point_cylinder.hpp"

#include <cmath>

#include "ancfnet/contact/distance/direction.hpp"

namespace ancfnet {

PointCylinderDistance CalcPointCylinderDistance(const Vector3d& p, const Vector3d& center,
                                                const Vector3d& axis, double radius,
                                                double half_length) {
  PointCylinderDistance out;
  const Vector3d r = p - center;
  const double z = axis.dot(r);
  const Vector3d v = r - z * axis;
  const double rho_p = v.norm();
  const bool on_axis = !(rho_p > 1e-12 * radius);
  const Vector3d e_r = on_axis ? AnyUnitPerpendicular(axis) : Vector3d(v / rho_p);
  const double sigma = z < 0.0 ? -1.0 : 1.0;
  const double dr = rho_p - radius;
  const double dz = std::abs(z) - half_length;
  // P/ρ_p: the curvature of the radial distance.
  const Matrix3d P_over_rho =
      on_axis ? Matrix3d::Zero()
              : Matrix3d((Matrix3d::Identity() - axis * axis.transpose() - e_r * e_r.transpose()) /
                         rho_p);
  const bool side = (dr > 0.0 && dz <= 0.0) || (dr <= 0.0 && dz <= 0.0 && dr >= dz);
  const bool cap = (dz > 0.0 && dr <= 0.0) || (dr <= 0.0 && dz <= 0.0 && dz > dr);
  out.inside = dr <= 0.0 && dz <= 0.0;
  if (side) {
    out.region = CylinderRegion::kSide;
    out.distance = dr;
    out.normal = e_r;
    out.closest_point = center + z * axis + radius * e_r;
    out.hessian = P_over_rho;
  } else if (cap) {
    out.region = CylinderRegion::kCap;
    out.distance = dz;
    out.normal = sigma * axis;
    out.closest_point = p - dz * out.normal;
    out.hessian.setZero();
  } else {
    out.region = CylinderRegion::kRim;
    out.distance = std::hypot(dr, dz);
    out.normal = (dr * e_r + dz * sigma * axis) / out.distance;
    out.closest_point = center + sigma * half_length * axis + radius * e_r;
    out.hessian = (e_r * e_r.transpose() + axis * axis.transpose() -
                   out.normal * out.normal.transpose() + dr * P_over_rho) /
                  out.distance;
  }
  return out;
}

}  // namespace ancfnet
