#include "ancfnet/analysis/net_metrics.hpp"

#include <cmath>

namespace ancfnet {

double CalcMouthArea(const std::vector<Vector3d>& polygon, const Vector3d& axis) {
  const Vector3d n = axis.normalized();
  // An in-plane basis (e1, e2) with e1 × e2 = n.
  const Vector3d helper = std::abs(n.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d e1 = n.cross(helper).normalized();
  const Vector3d e2 = n.cross(e1);
  double twice_area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vector3d& a = polygon[i];
    const Vector3d& b = polygon[(i + 1) % polygon.size()];
    twice_area += a.dot(e1) * b.dot(e2) - b.dot(e1) * a.dot(e2);
  }
  return 0.5 * std::abs(twice_area);
}

Vector3d CalcCentroid(const std::vector<Vector3d>& points, const std::vector<double>& masses) {
  Vector3d sum = Vector3d::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    sum += masses[i] * points[i];
    total += masses[i];
  }
  return sum / total;
}

}  // namespace ancfnet
