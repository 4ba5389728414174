#include "ancfnet/contact/mesh/mesh_bvh.hpp"

#include <algorithm>
#include <cassert>
#include <limits>
#include <utility>

#include "ancfnet/contact/distance/point_segment.hpp"
#include "ancfnet/contact/distance/point_sphere.hpp"
#include "ancfnet/contact/distance/point_triangle.hpp"

namespace ancfnet {
namespace {

// Squared distance of p to the box [lower, upper] (0 inside).
double BoxDistance2(const Vector3d& p, const Vector3d& lower, const Vector3d& upper) {
  return (p - p.cwiseMax(lower).cwiseMin(upper)).squaredNorm();
}

PointTriangleDistance TriangleDistance(const TriangleMesh& mesh, Index t, const Vector3d& p) {
  const auto tri = mesh.triangles.col(t);
  return CalcPointTriangleDistance(p, mesh.vertices.col(tri[0]), mesh.vertices.col(tri[1]),
                                   mesh.vertices.col(tri[2]));
}

}  // namespace

MeshBvh::MeshBvh(TriangleMesh mesh) : mesh_(std::move(mesh)), normals_(CalcMeshNormals(mesh_)) {
  assert(mesh_.triangles.cols() > 0);
  if (normals_.closed && normals_.volume < 0.0) {
    mesh_.triangles.row(1).swap(mesh_.triangles.row(2));
    normals_ = CalcMeshNormals(mesh_);
  }
  const Index n = mesh_.triangles.cols();
  Eigen::Matrix3Xd centroids(3, n);
  for (Index t = 0; t < n; ++t) {
    const auto tri = mesh_.triangles.col(t);
    centroids.col(t) =
        (mesh_.vertices.col(tri[0]) + mesh_.vertices.col(tri[1]) + mesh_.vertices.col(tri[2])) /
        3.0;
  }
  order_.resize(n);
  for (Index t = 0; t < n; ++t) order_[t] = static_cast<int>(t);
  nodes_.reserve(2 * (n / kLeafSize + 1));
  Build(0, static_cast<int>(n), 1, centroids);
}

int MeshBvh::Build(int begin, int end, int depth, const Eigen::Matrix3Xd& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  depth_ = std::max(depth_, depth);
  assert(depth_ < kMaxDepth);
  Vector3d lower = Vector3d::Constant(std::numeric_limits<double>::infinity());
  Vector3d upper = -lower;
  Vector3d c_lower = lower, c_upper = upper;
  for (int i = begin; i < end; ++i) {
    const auto tri = mesh_.triangles.col(order_[i]);
    for (int k = 0; k < 3; ++k) {
      lower = lower.cwiseMin(mesh_.vertices.col(tri[k]));
      upper = upper.cwiseMax(mesh_.vertices.col(tri[k]));
    }
    c_lower = c_lower.cwiseMin(centroids.col(order_[i]));
    c_upper = c_upper.cwiseMax(centroids.col(order_[i]));
  }
  nodes_[index].lower = lower;
  nodes_[index].upper = upper;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  Index axis = 0;
  (c_upper - c_lower).maxCoeff(&axis);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return centroids(axis, a) < centroids(axis, b); });
  Build(begin, mid, depth + 1, centroids);
  const int right = Build(mid, end, depth + 1, centroids);
  nodes_[index].first = right;
  return index;
}

MeshDistance MeshBvh::CalcDistance(const Vector3d& p) const {
  // (node, squared distance to its box); the descent holds at most depth + 1 entries.
  std::array<std::pair<int, double>, kMaxDepth + 1> stack;
  int top = 0;
  stack[top++] = {0, BoxDistance2(p, nodes_[0].lower, nodes_[0].upper)};
  double best2 = std::numeric_limits<double>::infinity();
  Index best = -1;
  while (top > 0) {
    const auto [index, box2] = stack[--top];
    if (box2 >= best2) continue;
    const Node& node = nodes_[index];
    if (node.count > 0) {
      // Squared distances only; the closest point and its derivatives for the nearest alone.
      for (int i = node.first; i < node.first + node.count; ++i) {
        const auto tri = mesh_.triangles.col(order_[i]);
        const double d2 = CalcPointTriangleSquaredDistance(
            p, mesh_.vertices.col(tri[0]), mesh_.vertices.col(tri[1]), mesh_.vertices.col(tri[2]));
        if (d2 < best2) {
          best2 = d2;
          best = order_[i];
        }
      }
      continue;
    }
    const int left = index + 1, right = node.first;
    const double left2 = BoxDistance2(p, nodes_[left].lower, nodes_[left].upper);
    const double right2 = BoxDistance2(p, nodes_[right].lower, nodes_[right].upper);
    // The nearer child goes on top, to be searched first.
    if (left2 <= right2) {
      if (right2 < best2) stack[top++] = {right, right2};
      if (left2 < best2) stack[top++] = {left, left2};
    } else {
      if (left2 < best2) stack[top++] = {left, left2};
      if (right2 < best2) stack[top++] = {right, right2};
    }
  }
  return Finish(p, best, best < 0 ? PointTriangleDistance{} : TriangleDistance(mesh_, best, p));
}

MeshDistance MeshBvh::CalcDistanceBruteForce(const Vector3d& p) const {
  Index best = -1;
  PointTriangleDistance best_distance;
  best_distance.distance = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < mesh_.triangles.cols(); ++t) {
    const PointTriangleDistance d = TriangleDistance(mesh_, t, p);
    if (d.distance < best_distance.distance) {
      best = t;
      best_distance = d;
    }
  }
  return Finish(p, best, best_distance);
}

MeshDistance MeshBvh::Finish(const Vector3d& p, Index t, const PointTriangleDistance& d) const {
  MeshDistance out;
  if (t < 0) {  // p not finite: no triangle compared nearer than infinity
    out.distance = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  out.triangle = t;
  out.closest_point = d.closest_point;
  const auto tri = mesh_.triangles.col(t);
  Vector3d pseudo_normal;
  Matrix3d curvature = Matrix3d::Zero();  // ∂u/∂p
  switch (d.region) {
    case TriangleRegion::kFace: {
      // The height over the face's plane: n exactly the face normal, also where d is rounding.
      out.feature = MeshFeature::kFace;
      out.feature_index = t;
      const Vector3d n_f = normals_.face.col(t);
      const double height = (p - d.closest_point).dot(n_f);
      const double s = closed() || height >= 0.0 ? 1.0 : -1.0;
      out.distance = s * height;
      out.normal = s * n_f;
      return out;
    }
    case TriangleRegion::kEdgeAB:
    case TriangleRegion::kEdgeBC:
    case TriangleRegion::kEdgeCA: {
      const int k = static_cast<int>(d.region) - static_cast<int>(TriangleRegion::kEdgeAB);
      out.feature = MeshFeature::kEdge;
      out.feature_index = normals_.triangle_edges(k, t);
      pseudo_normal = normals_.edge.col(out.feature_index);
      const Vector3d a = mesh_.vertices.col(tri[k]), b = mesh_.vertices.col(tri[(k + 1) % 3]);
      curvature = CalcPointSegmentHessian(CalcPointSegmentDistance(p, a, b), a, b);
      break;
    }
    case TriangleRegion::kVertexA:
    case TriangleRegion::kVertexB:
    case TriangleRegion::kVertexC: {
      const int k = static_cast<int>(d.region) - static_cast<int>(TriangleRegion::kVertexA);
      out.feature = MeshFeature::kVertex;
      out.feature_index = tri[k];
      pseudo_normal = normals_.vertex.col(out.feature_index);
      curvature = CalcPointSphereDistance(p, mesh_.vertices.col(tri[k]), 0.0).hessian;
      break;
    }
  }
  if (!(d.distance > 0.0)) {
    out.distance = 0.0;
    out.normal = closed() ? pseudo_normal : d.direction;
    return out;
  }
  const double s = !closed() || (p - d.closest_point).dot(pseudo_normal) >= 0.0 ? 1.0 : -1.0;
  out.distance = s * d.distance;
  out.normal = s * d.direction;
  out.hessian = s * curvature;
  return out;
}

}  // namespace ancfnet
