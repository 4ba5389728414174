#include "ancfnet/contact/mesh/mesh_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "ancfnet/contact/distance/direction.hpp"

namespace ancfnet {
namespace {

// The angle at vertex a of the triangle (a, b, c), robust near 0 and π.
double AngleAt(const Vector3d& a, const Vector3d& b, const Vector3d& c) {
  const Vector3d u = b - a, v = c - a;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

MeshNormals CalcMeshNormals(const TriangleMesh& mesh) {
  const Index nt = mesh.triangles.cols();
  const Index nv = mesh.vertices.cols();
  MeshNormals out;
  out.face.resize(3, nt);
  out.triangle_edges.resize(3, nt);
  out.vertex = Eigen::Matrix3Xd::Zero(3, nv);
  // Per edge (keyed by its sorted vertex pair): its index, and the sum of the directions it is
  // run through (+1 from low to high vertex): 0 for two consistently oriented triangles.
  std::unordered_map<std::uint64_t, Index> edge_of;
  std::vector<Vector3d> edge_sum;
  std::vector<int> uses, direction;
  for (Index t = 0; t < nt; ++t) {
    const Eigen::Vector3i tri = mesh.triangles.col(t);
    const Vector3d a = mesh.vertices.col(tri[0]), b = mesh.vertices.col(tri[1]),
                   c = mesh.vertices.col(tri[2]);
    const Vector3d cross = (b - a).cross(c - a);
    const bool proper = cross.norm() > 0.0;
    const Vector3d n = proper ? Vector3d(cross.normalized()) : Vector3d::UnitZ();
    out.face.col(t) = n;
    out.volume += a.dot(b.cross(c)) / 6.0;
    if (proper) {
      out.vertex.col(tri[0]) += AngleAt(a, b, c) * n;
      out.vertex.col(tri[1]) += AngleAt(b, c, a) * n;
      out.vertex.col(tri[2]) += AngleAt(c, a, b) * n;
    }
    for (int k = 0; k < 3; ++k) {
      const int i = tri[k], j = tri[(k + 1) % 3];
      const std::uint64_t lo = std::min(i, j), hi = std::max(i, j);
      const auto [it, inserted] =
          edge_of.try_emplace((lo << 32) | hi, static_cast<Index>(edge_sum.size()));
      if (inserted) {
        edge_sum.push_back(Vector3d::Zero());
        uses.push_back(0);
        direction.push_back(0);
      }
      const Index e = it->second;
      out.triangle_edges(k, t) = static_cast<int>(e);
      if (proper) edge_sum[e] += n;
      ++uses[e];
      direction[e] += i < j ? 1 : -1;
    }
  }
  const Index ne = static_cast<Index>(edge_sum.size());
  out.edge.resize(3, ne);
  out.closed = true;
  for (Index e = 0; e < ne; ++e) {
    out.edge.col(e) = NormalizedOr(edge_sum[e], Vector3d::UnitZ());
    if (uses[e] != 2 || direction[e] != 0) out.closed = false;
  }
  for (Index v = 0; v < nv; ++v)
    out.vertex.col(v) = NormalizedOr(out.vertex.col(v), Vector3d::UnitZ());
  return out;
}

}  // namespace ancfnet
