#include "ancfnet/contact/distance/direction.hpp"

namespace ancfnet {

Vector3d AnyUnitPerpendicular(const Vector3d& v) {
  const double norm = v.norm();
  if (!(norm > 0.0)) return Vector3d::UnitZ();
  Index k = 0;
  v.cwiseAbs().minCoeff(&k);
  const Vector3d w = v.cross(Vector3d::Unit(k));
  return w / w.norm();
}

Vector3d NormalizedOr(const Vector3d& v, const Vector3d& fallback) {
  const double norm = v.norm();
  return norm > 0.0 ? Vector3d(v / norm) : fallback;
}

}  // namespace ancfnet
