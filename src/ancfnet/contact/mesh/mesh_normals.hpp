#pragma once
/// @file The edges of a triangle mesh and the angle-weighted pseudo-normals of its faces, edges
/// and vertices, which sign the distance to a closed mesh.

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/mesh/triangle_mesh.hpp"

namespace ancfnet {

/// Edges and pseudo-normals of a mesh (all normals unit).
struct MeshNormals {
  Eigen::Matrix3Xd face;    ///< n_f = (b − a) × (c − a)/|…| of each triangle (a, b, c)
  Eigen::Matrix3Xd edge;    ///< pseudo-normal of each edge
  Eigen::Matrix3Xd vertex;  ///< pseudo-normal of each vertex
  Eigen::Matrix3Xi triangle_edges;  ///< the edges AB, BC, CA of each triangle
  /// Every edge borders exactly two triangles that run through it in opposite directions (a
  /// closed, consistently oriented surface: the distance can be signed).
  bool closed = false;
  double volume = 0.0;  ///< enclosed volume Σ a·(b × c)/6 (m³); meaningful where closed
};

/// Pseudo-normals after Bærentzen & Aanæs (2005): an edge's is n₁ + n₂ of its two triangles (n₁
/// for a boundary edge), a vertex's is Σ α_f n_f over its triangles, α_f the triangle's angle at
/// the vertex; both normalised. For a closed mesh and a point p whose closest surface point x lies
/// on a feature with pseudo-normal N, sign((p − x)·N) is the sign of the signed distance (> 0
/// outside), at faces, edges and vertices alike. A degenerate triangle (zero area) has the normal
/// e_z and no weight in its vertices and edges.
MeshNormals CalcMeshNormals(const TriangleMesh& mesh);

}  // namespace ancfnet
