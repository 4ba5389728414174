#include "ancfnet/contact/distance/point_box.hpp"

#include <algorithm>
#include <cmath>

namespace ancfnet {

PointBoxDistance CalcPointBoxDistance(const Vector3d& p, const Vector3d& center,
                                      const Vector3d& half_extents, const Matrix3d& R_WB) {
  PointBoxDistance out;
  const Vector3d q = R_WB.transpose() * (p - center);
  const Vector3d clamped = q.cwiseMax(-half_extents).cwiseMin(half_extents);
  const Vector3d w = q - clamped;
  const double outside = w.norm();
  if (outside > 0.0) {
    out.distance = outside;
    const Vector3d n_B = w / outside;
    Matrix3d mask = Matrix3d::Zero();
    for (int k = 0; k < 3; ++k) mask(k, k) = w[k] != 0.0 ? 1.0 : 0.0;
    out.normal = R_WB * n_B;
    out.closest_point = center + R_WB * clamped;
    out.hessian = R_WB * (mask - n_B * n_B.transpose()) * R_WB.transpose() / outside;
    return out;
  }
  out.inside = true;
  int k = 0;
  double depth = half_extents[0] - std::abs(q[0]);
  for (int i = 1; i < 3; ++i) {
    const double di = half_extents[i] - std::abs(q[i]);
    if (di < depth) {
      depth = di;
      k = i;
    }
  }
  const double sign = q[k] < 0.0 ? -1.0 : 1.0;
  Vector3d on_face = q;
  on_face[k] = sign * half_extents[k];
  out.distance = -depth;
  out.normal = sign * R_WB.col(k);
  out.closest_point = center + R_WB * on_face;
  out.hessian.setZero();
  return out;
}

}  // namespace ancfnet
