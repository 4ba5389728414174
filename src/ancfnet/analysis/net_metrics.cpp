#include "ancfnet/analysis/net_metrics.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

Vector3d UnitAxis(const Vector3d& axis, const char* what) {
  const double norm = axis.norm();
  if (!(norm > 0.0 && std::isfinite(norm)))
    throw InputError(fmt::format("the {} axis must be a non-zero finite vector (got [{}, {}, {}])",
                                 what, axis.x(), axis.y(), axis.z()));
  return axis / norm;
}

}  // namespace

double CalcMouthArea(const std::vector<Vector3d>& polygon, const Vector3d& axis) {
  const Vector3d n = UnitAxis(axis, "mouth-area");
  if (polygon.size() < 3) return 0.0;
  // Twice the vector area of the polygon, measured from its first vertex: the terms of the
  // first and last edges vanish, the others are products of in-net distances only.
  const Vector3d& origin = polygon.front();
  Vector3d twice_area = Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    twice_area += (polygon[i] - origin).cross(polygon[i + 1] - origin);
  return 0.5 * std::abs(twice_area.dot(n));
}

Vector3d CalcCentroid(const std::vector<Vector3d>& points, const std::vector<double>& masses) {
  if (points.size() != masses.size())
    throw InputError(
        fmt::format("centroid of {} points given {} masses", points.size(), masses.size()));
  if (points.empty()) throw InputError("the centroid of no points is undefined");
  Vector3d sum = Vector3d::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(masses[i] >= 0.0))
      throw InputError(
          fmt::format("mass {} of the centroid is {} kg: masses must be >= 0", i, masses[i]));
    sum += masses[i] * points[i];
    total += masses[i];
  }
  if (!(total > 0.0 && std::isfinite(total)))
    throw InputError(fmt::format("the total mass of a centroid must be > 0 (got {} kg)", total));
  return sum / total;
}

Vector3d CalcCentroid(const std::vector<Vector3d>& points) {
  if (points.empty()) throw InputError("the centroid of no points is undefined");
  Vector3d sum = Vector3d::Zero();
  for (const Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

double CalcDistanceTravelled(const Vector3d& start, const Vector3d& now, const Vector3d& axis) {
  return (now - start).dot(UnitAxis(axis, "travel"));
}

}  // namespace ancfnet
