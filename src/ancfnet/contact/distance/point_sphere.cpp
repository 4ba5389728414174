#include "ancfnet/contact/distance/point_sphere.hpp"

#include <algorithm>

namespace ancfnet {

PointSphereDistance CalcPointSphereDistance(const Vector3d& p, const Vector3d& c, double radius) {
  PointSphereDistance out;
  const Vector3d r = p - c;
  const double rho = r.norm();
  out.distance = rho - radius;
  if (rho <= 1e-12 * std::max(radius, 1e-300)) {
    out.at_center = true;
    out.normal = Vector3d::UnitZ();
    out.hessian.setZero();
  } else {
    out.normal = r / rho;
    out.hessian = (Matrix3d::Identity() - out.normal * out.normal.transpose()) / rho;
  }
  out.closest_point = c + radius * out.normal;
  return out;
}

}  // namespace ancfnet
