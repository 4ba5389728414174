#include "ancfnet/contact/distance/point_plane.hpp"

namespace ancfnet {

PointPlaneDistance CalcPointPlaneDistance(const Vector3d& p, const Vector3d& o, const Vector3d& n) {
  PointPlaneDistance out;
  out.distance = n.dot(p - o);
  out.closest_point = p - out.distance * n;
  out.gradient_p = n;
  return out;
}

}  // namespace ancfnet
