#pragma once
/// @file The convex hull of a point set in 3D, as the planes of its facets, for inside tests:
/// how much of a target a net encloses (analysis/capture_metrics.hpp).

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// The convex hull of points (m), built by the incremental algorithm (Preparata & Hong 1977;
/// de Berg et al., "Computational Geometry", 3rd ed. 2008, ch. 11): a first tetrahedron of four
/// extreme points, then each point outside the hull replaces the facets it sees by a fan of
/// facets over their horizon (the visible facets found by a search across edges from the one
/// the point sees best, which keeps the surface closed when rounding blurs nearly coplanar
/// facets, e.g. a net that is almost flat). O(n²) in the worst case. Points within `tolerance` of
/// a facet's plane count as on it, with tolerance = 10⁻⁹ × the diameter of the points' bounding
/// box.
/// Points that span no volume (fewer than four, or all on one plane or line) give an empty hull:
/// it holds no point.
class ConvexHull {
 public:
  /// One facet's plane n·x = offset with the outward unit normal n.
  struct Facet {
    Vector3d normal = Vector3d::UnitZ();
    double offset = 0.0;  ///< m
  };

  explicit ConvexHull(const std::vector<Vector3d>& points);

  /// True when the points span no volume.
  bool empty() const { return facets_.empty(); }
  const std::vector<Facet>& facets() const { return facets_; }

  /// True when x is inside the hull or on its boundary: n·x ≤ offset + tolerance for every
  /// facet (a point is outside a convex polyhedron iff one facet's plane separates it).
  bool Contains(const Vector3d& x) const;

  /// Fraction of the ball |x − center| ≤ radius (m, > 0) inside the hull, estimated on the
  /// deterministic sample of the ball: the centres of the cells of a grid of `cells_per_axis`³
  /// cubes over the ball's bounding cube that lie in the ball. Exact for a ball inside the hull
  /// (1) or outside it (0); for a half-space bounded by a plane through the centre normal to an
  /// axis, ½ when the number of cells is even (the sample is symmetric and none lies on the
  /// plane). 16 cells per axis give 2176 samples, a fraction to about ±1 % for smooth boundaries.
  double CalcBallFractionInside(const Vector3d& center, double radius,
                                int cells_per_axis = 16) const;

 private:
  std::vector<Facet> facets_;
  double tolerance_ = 0.0;
};

}  // namespace ancfnet
