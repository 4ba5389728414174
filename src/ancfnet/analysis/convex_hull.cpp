#include "ancfnet/analysis/convex_hull.hpp"

#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// A triangle (a, b, c) wound counter-clockwise seen from outside, with its plane.
struct Triangle {
  std::array<int, 3> v{};
  Vector3d normal = Vector3d::Zero();
  double offset = 0.0;
  bool alive = true;
};

class IncrementalHull {
 public:
  IncrementalHull(const std::vector<Vector3d>& points, double tolerance)
      : points_(points), tolerance_(tolerance) {}

  // Builds the hull; false when the points span no volume.
  bool Build() {
    std::array<int, 4> first{};
    if (!FindFirstTetrahedron(&first)) return false;
    interior_ = Vector3d::Zero();
    for (int i : first) interior_ += points_[i] / 4.0;
    const auto [a, b, c, d] = first;
    for (const std::array<int, 3>& face :
         {std::array{a, b, c}, std::array{a, b, d}, std::array{a, c, d}, std::array{b, c, d}})
      AddTriangle(Outward(face));
    for (int p = 0; p < static_cast<int>(points_.size()); ++p) AddPoint(p);
    return true;
  }

  std::vector<ConvexHull::Facet> Facets() const {
    std::vector<ConvexHull::Facet> facets;
    for (const Triangle& t : triangles_)
      if (t.alive) facets.push_back({.normal = t.normal, .offset = t.offset});
    return facets;
  }

 private:
  // Four points spanning a volume: the extremes in x, the farthest from their line, the
  // farthest from the plane of the three.
  bool FindFirstTetrahedron(std::array<int, 4>* first) const {
    const int n = static_cast<int>(points_.size());
    if (n < 4) return false;
    int i0 = 0;
    int i1 = 0;
    for (int i = 1; i < n; ++i) {
      if (points_[i].x() < points_[i0].x()) i0 = i;
      if (points_[i].x() > points_[i1].x()) i1 = i;
    }
    if (i0 == i1) {  // all at one x: take the farthest from the first point
      for (int i = 0; i < n; ++i)
        if ((points_[i] - points_[i0]).norm() > (points_[i1] - points_[i0]).norm()) i1 = i;
    }
    if ((points_[i1] - points_[i0]).norm() <= tolerance_) return false;
    const Vector3d line = (points_[i1] - points_[i0]).normalized();
    int i2 = -1;
    double best = tolerance_;
    for (int i = 0; i < n; ++i) {
      const double d = (points_[i] - points_[i0]).cross(line).norm();
      if (d > best) best = d, i2 = i;
    }
    if (i2 < 0) return false;
    const Vector3d normal =
        (points_[i1] - points_[i0]).cross(points_[i2] - points_[i0]).normalized();
    int i3 = -1;
    best = tolerance_;
    for (int i = 0; i < n; ++i) {
      const double d = std::abs(normal.dot(points_[i] - points_[i0]));
      if (d > best) best = d, i3 = i;
    }
    if (i3 < 0) return false;
    *first = {i0, i1, i2, i3};
    return true;
  }

  // The face wound so that its normal points away from the interior point.
  std::array<int, 3> Outward(std::array<int, 3> face) const {
    const Vector3d& a = points_[face[0]];
    const Vector3d n = (points_[face[1]] - a).cross(points_[face[2]] - a);
    if (n.dot(interior_ - a) > 0.0) std::swap(face[1], face[2]);
    return face;
  }

  static long long EdgeKey(int from, int to) {
    return (static_cast<long long>(from) << 32) | static_cast<unsigned int>(to);
  }

  void AddTriangle(const std::array<int, 3>& v) {
    Triangle t;
    t.v = v;
    const Vector3d& a = points_[v[0]];
    t.normal = (points_[v[1]] - a).cross(points_[v[2]] - a).normalized();
    t.offset = t.normal.dot(a);
    const int index = static_cast<int>(triangles_.size());
    for (int k = 0; k < 3; ++k) edges_[EdgeKey(v[k], v[(k + 1) % 3])] = index;
    triangles_.push_back(t);
  }

  bool Sees(const Triangle& t, int p) const {
    return t.alive && t.normal.dot(points_[p]) - t.offset > tolerance_;
  }

  // The facet across the edge (a, b) of a facet: the one with the edge (b, a); −1 if none.
  int Neighbour(int a, int b) const {
    const auto found = edges_.find(EdgeKey(b, a));
    return found == edges_.end() ? -1 : found->second;
  }

  // Replaces the facets p sees by the fan from p over their horizon. The visible facets are
  // gathered by a search across edges from the one p sees best, so that they form one connected
  // region even where rounding makes a nearly coplanar facet elsewhere look visible; the horizon
  // is the edges (a, b) of that region whose neighbour across them is outside it.
  void AddPoint(int p) {
    int first = -1;
    double farthest = tolerance_;
    for (int i = 0; i < static_cast<int>(triangles_.size()); ++i) {
      if (!triangles_[i].alive) continue;
      const double d = triangles_[i].normal.dot(points_[p]) - triangles_[i].offset;
      if (d > farthest) farthest = d, first = i;
    }
    if (first < 0) return;
    std::vector<int> visible{first};
    std::unordered_set<int> in_region{first};
    for (std::size_t next = 0; next < visible.size(); ++next) {
      const std::array<int, 3> v = triangles_[visible[next]].v;
      for (int k = 0; k < 3; ++k) {
        const int neighbour = Neighbour(v[k], v[(k + 1) % 3]);
        if (neighbour >= 0 && !in_region.count(neighbour) && Sees(triangles_[neighbour], p)) {
          in_region.insert(neighbour);
          visible.push_back(neighbour);
        }
      }
    }
    std::vector<std::array<int, 2>> horizon;
    for (int i : visible) {
      const std::array<int, 3> v = triangles_[i].v;
      for (int k = 0; k < 3; ++k)
        if (!in_region.count(Neighbour(v[k], v[(k + 1) % 3])))
          horizon.push_back({v[k], v[(k + 1) % 3]});
    }
    for (int i : visible) {
      triangles_[i].alive = false;
      const std::array<int, 3> v = triangles_[i].v;
      for (int k = 0; k < 3; ++k) edges_.erase(EdgeKey(v[k], v[(k + 1) % 3]));
    }
    for (const auto& [a, b] : horizon) AddTriangle({a, b, p});
  }

  const std::vector<Vector3d>& points_;
  double tolerance_;
  Vector3d interior_ = Vector3d::Zero();
  std::vector<Triangle> triangles_;
  std::unordered_map<long long, int> edges_;  // directed edge → the facet it belongs to
};

}  // namespace

ConvexHull::ConvexHull(const std::vector<Vector3d>& points) {
  if (points.empty()) return;
  Vector3d lower = points[0];
  Vector3d upper = points[0];
  for (const Vector3d& p : points) {
    if (!p.allFinite()) throw InputError("convex hull of a non-finite point");
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  tolerance_ = 1e-9 * (upper - lower).norm();
  IncrementalHull hull(points, tolerance_);
  if (hull.Build()) facets_ = hull.Facets();
}

bool ConvexHull::Contains(const Vector3d& x) const {
  if (facets_.empty()) return false;
  for (const Facet& f : facets_)
    if (f.normal.dot(x) > f.offset + tolerance_) return false;
  return true;
}

double ConvexHull::CalcBallFractionInside(const Vector3d& center, double radius,
                                          int cells_per_axis) const {
  if (!(radius > 0.0) || !std::isfinite(radius) || cells_per_axis < 1)
    throw InputError("a ball's radius must be positive and finite, with at least 1 cell");
  const double cell = 2.0 / cells_per_axis;  // in units of the radius
  int in_ball = 0;
  int inside = 0;
  for (int i = 0; i < cells_per_axis; ++i)
    for (int j = 0; j < cells_per_axis; ++j)
      for (int k = 0; k < cells_per_axis; ++k) {
        const Vector3d u((i + 0.5) * cell - 1.0, (j + 0.5) * cell - 1.0, (k + 0.5) * cell - 1.0);
        if (u.squaredNorm() > 1.0) continue;
        ++in_ball;
        if (Contains(center + radius * u)) ++inside;
      }
  return static_cast<double>(inside) / in_ball;
}

}  // namespace ancfnet
