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

double CalcPointTriangleSquaredDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                        const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a;
  const Vector3d ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.squaredNorm();  // vertex a
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.squaredNorm();  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)  // edge ab
    return (ap - d1 / (d1 - d3) * ab).squaredNorm();
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.squaredNorm();  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)  // edge ac
    return (ap - d2 / (d2 - d6) * ac).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)  // edge bc
    return (bp - (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)).squaredNorm();
  // The face: barycentric (va, vb, vc) / (va + vb + vc).
  const double sum = va + vb + vc;
  const double distance2 = (ap - (vb / sum) * ab - (vc / sum) * ac).squaredNorm();
  if (std::isfinite(distance2)) return distance2;
  const double d = CalcPointTriangleDistance(p, a, b, c).distance;
  return d * d;
}

}  // namespace ancfnet
