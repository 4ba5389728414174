#include "ancfnet/contact/distance/point_triangle.hpp"

#include <cmath>
#include <limits>

#include "ancfnet/contact/distance/direction.hpp"
#include "ancfnet/contact/distance/point_segment.hpp"

namespace ancfnet {
namespace {

// Keeps the nearest of the three edges; `first`/`second` index the edge's end vertices.
void ConsiderEdge(const Vector3d& p, const Vector3d& v0, const Vector3d& v1, int first, int second,
                  TriangleRegion edge, TriangleRegion vertex0, TriangleRegion vertex1,
                  PointTriangleDistance* best) {
  const PointSegmentDistance ps = CalcPointSegmentDistance(p, v0, v1);
  if (ps.distance >= best->distance) return;
  best->distance = ps.distance;
  best->closest_point = ps.closest_point;
  best->barycentric.setZero();
  best->barycentric[first] = 1.0 - ps.t;
  best->barycentric[second] = ps.t;
  best->direction = ps.direction;
  switch (ps.region) {
    case PointSegmentRegion::kEndA:
      best->region = vertex0;
      break;
    case PointSegmentRegion::kEndB:
      best->region = vertex1;
      break;
    case PointSegmentRegion::kInterior:
      best->region = edge;
      break;
  }
}

}  // namespace

PointTriangleDistance CalcPointTriangleDistance(const Vector3d& p, const Vector3d& a,
                                                const Vector3d& b, const Vector3d& c) {
  PointTriangleDistance out;
  const Vector3d ab = b - a;
  const Vector3d ac = c - a;
  const Vector3d ap = p - a;
  const Vector3d n = ab.cross(ac);
  const double area2 = n.squaredNorm();
  bool on_face = false;
  if (area2 > 1e-24 * ab.squaredNorm() * ac.squaredNorm() && area2 > 0.0) {
    const double lb = ap.cross(ac).dot(n) / area2;
    const double lc = ab.cross(ap).dot(n) / area2;
    const double la = 1.0 - lb - lc;
    if (la >= 0.0 && lb >= 0.0 && lc >= 0.0) {
      on_face = true;
      out.barycentric = Vector3d(la, lb, lc);
      out.closest_point = la * a + lb * b + lc * c;
      out.region = TriangleRegion::kFace;
      const Vector3d r = p - out.closest_point;
      out.distance = r.norm();
      out.direction = NormalizedOr(r, n / std::sqrt(area2));
    }
  }
  if (!on_face) {
    out.distance = std::numeric_limits<double>::infinity();
    ConsiderEdge(p, a, b, 0, 1, TriangleRegion::kEdgeAB, TriangleRegion::kVertexA,
                 TriangleRegion::kVertexB, &out);
    ConsiderEdge(p, b, c, 1, 2, TriangleRegion::kEdgeBC, TriangleRegion::kVertexB,
                 TriangleRegion::kVertexC, &out);
    ConsiderEdge(p, c, a, 2, 0, TriangleRegion::kEdgeCA, TriangleRegion::kVertexC,
                 TriangleRegion::kVertexA, &out);
    // A point on the boundary of a proper triangle: the face normal, as for the face.
    if (out.distance == 0.0 && area2 > 0.0) out.direction = n / std::sqrt(area2);
  }
  const Vector3d& u = out.direction;
  out.gradient << u, -out.barycentric[0] * u, -out.barycentric[1] * u, -out.barycentric[2] * u;
  return out;
}

}  // namespace ancfnet
