#pragma once
/// @file The design of a net as a graph: knot positions and the threads between them, plus the
/// perimeter (the mouth) and the corners. Pure geometry; model/net_builder.hpp turns it into
/// cables, knots and links.

#include <array>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

struct NetTopology {
  std::vector<Vector3d> knots;                ///< knot positions (m)
  std::vector<std::array<Index, 2>> threads;  ///< knot pairs
  std::vector<Index> perimeter;               ///< knots around the net, in order (closed)
  std::vector<Index> corners;                 ///< corner knots, in perimeter order
};

/// A rectangular net of side_u × side_v (m) with meshes_u × meshes_v square-ish meshes, centred
/// at `center`, lying in the plane of the orthonormal unit vectors axis_u, axis_v (its normal
/// axis_u × axis_v is the launch axis). `diamond` turns the mesh by 45°: the threads run along
/// the diagonals of the outline (the square net rotated by 45° about its normal, so its corners
/// point along ±axis_u and ±axis_v; side_u = side_v required).
struct GridNetSpec {
  double side_u = 1.0;
  double side_v = 1.0;
  int meshes_u = 1;
  int meshes_v = 1;
  Vector3d center = Vector3d::Zero();
  Vector3d axis_u = Vector3d::UnitX();
  Vector3d axis_v = Vector3d::UnitY();
  bool diamond = false;
};

/// Knots on the (meshes_u + 1) × (meshes_v + 1) grid, numbered row by row (index = i + (n_u + 1) j
/// for knot i along u and j along v), threads along both grid directions:
/// n_u (n_v + 1) + n_v (n_u + 1) of them. Throws InputError on invalid values.
NetTopology MakeGridNet(const GridNetSpec& spec);

/// Meshes along a side of length `side` for a mesh size (both m): the nearest whole number ≥ 1.
int MeshesForSize(double side, double mesh_size);

/// A net given as an explicit graph. Throws InputError for a thread index out of range, a
/// thread from a knot to itself, a repeated thread, coincident knots of a thread, or a perimeter
/// index out of range.
NetTopology MakeGraphNet(std::vector<Vector3d> knots, std::vector<std::array<Index, 2>> threads,
                         std::vector<Index> perimeter = {}, std::vector<Index> corners = {});

}  // namespace ancfnet
