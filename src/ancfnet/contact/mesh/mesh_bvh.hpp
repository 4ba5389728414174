#pragma once
/// @file A triangle mesh target ready for queries: an axis-aligned bounding-volume hierarchy over
/// its triangles and the signed (closed mesh) or unsigned (open mesh) distance of a point, with
/// the outward normal and the Hessian that a contact force's stiffness needs.

#include <array>
#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/distance/point_triangle.hpp"
#include "ancfnet/contact/mesh/mesh_normals.hpp"
#include "ancfnet/contact/mesh/triangle_mesh.hpp"

namespace ancfnet {

/// The feature of the mesh that holds the closest point.
enum class MeshFeature { kFace, kEdge, kVertex };

/// Distance of a point to a mesh and its derivatives with respect to the point.
struct MeshDistance {
  /// φ (m): closed mesh, the signed distance (< 0 inside); open mesh, the unsigned distance ≥ 0.
  double distance = 0.0;
  Vector3d closest_point = Vector3d::Zero();  ///< x on the surface (m): p = x + φ n
  Vector3d normal = Vector3d::UnitZ();        ///< n = ∂φ/∂p, unit
  Matrix3d hessian = Matrix3d::Zero();        ///< ∂²φ/∂p² = ∂n/∂p (1/m)
  MeshFeature feature = MeshFeature::kFace;
  Index triangle = -1;       ///< a triangle holding x (the mesh's numbering)
  Index feature_index = -1;  ///< the index of the face, edge (MeshNormals) or vertex
};

/// A rigid mesh and its bounding-volume hierarchy, built once: nodes are the bounding boxes of
/// their triangles, split at the median of the triangle centroids along the longest axis of
/// their bounding box, down to leaves of at most 4 triangles (depth ⌈log₂(n/4)⌉ + 1).
/// Distance (docs/theory.md, "Capsule and mesh targets"): the closest point x over all
/// triangles (CalcPointTriangleDistance), with d = |p − x| and u = (p − x)/d;
///   closed mesh: s = sign((p − x)·N), N the pseudo-normal of the feature holding x
///     (CalcMeshNormals), φ = s d, n = s u;
///   open mesh (a sheet of thickness 0, each side repelling): φ = d, n = u;
///   on a face, with its normal n_f and the height h = (p − x)·n_f, these are evaluated as
///   φ = h, n = n_f (closed) and φ = |h|, n = sign(h) n_f (open; + for h = 0), so that n is the
///   face normal to the last digit, even where d is rounding;
///   ∂n/∂p = 0 on a face, s (I − e eᵀ − u uᵀ)/d on an edge of direction e, s (I − u uᵀ)/d at a
///   vertex (s = 1 for an open mesh).
/// On an edge or a vertex at d = 0: φ = 0, n = N (closed) or a normal of the triangle found
/// (open), Hessian 0. A point that is not finite gets φ = NaN (so no contact), n = e_z, Hessian 0
/// and triangle −1.
/// Limitation of the open mesh: a probe whose centre crosses the sheet within one step is then
/// pushed out on the far side.
class MeshBvh {
 public:
  /// Builds the hierarchy and the pseudo-normals. A closed mesh whose enclosed volume is
  /// negative (triangles clockwise seen from outside) is reoriented. Precondition: at least one
  /// triangle (LoadTriangleMesh ensures it).
  explicit MeshBvh(TriangleMesh mesh);

  const TriangleMesh& mesh() const { return mesh_; }
  const MeshNormals& normals() const { return normals_; }
  /// A closed, consistently oriented surface: the distance is signed.
  bool closed() const { return normals_.closed; }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  int depth() const { return depth_; }

  /// The distance of p (m) by a depth-first branch-and-bound descent (nearer child first,
  /// subtrees whose box is farther than the best triangle so far skipped); no allocation.
  MeshDistance CalcDistance(const Vector3d& p) const;
  /// The same by testing every triangle (O(n)): the reference for tests and benchmarks.
  MeshDistance CalcDistanceBruteForce(const Vector3d& p) const;

 private:
  struct Node {
    Vector3d lower, upper;  // bounding box
    int first = 0;          // leaf: first triangle in order_; inner: index of the right child
    int count = 0;          // leaf: number of triangles; inner: 0 (left child at index + 1)
  };
  static constexpr int kLeafSize = 4;
  static constexpr int kMaxDepth = 64;  // the size of the query's stack

  int Build(int begin, int end, int depth, const Eigen::Matrix3Xd& centroids);
  MeshDistance Finish(const Vector3d& p, Index triangle, const PointTriangleDistance& d) const;

  TriangleMesh mesh_;
  MeshNormals normals_;
  std::vector<Node> nodes_;
  std::vector<int> order_;  // triangle indices, leaf by leaf
  int depth_ = 0;
};

}  // namespace ancfnet
