#pragma once
/// @file The design of a net as a graph: knot positions and the threads between them, plus the
/// perimeter (the mouth) and the corners. Pure geometry; model/net_builder.hpp turns it into
/// cables, knots and links.

#include <array>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// A net as a graph of knots joined by threads (straight segments in the design).
struct NetTopology {
  std::vector<Vector3d> knots;                ///< knot positions (m)
  std::vector<std::array<Index, 2>> threads;  ///< knot pairs, each pair once
  /// Knots around the net in order, each once: a closed polygon (the last joined to the first).
  /// Empty when unknown.
  std::vector<Index> perimeter;
  std::vector<Index> corners;  ///< corner knots (4 for grid nets), in perimeter order
};

/// A rectangular grid net of side_u × side_v (m) with meshes_u × meshes_v rectangular meshes,
/// centred at `center` (m), lying in the plane of the unit vectors axis_u, axis_v (orthogonal);
/// its normal n = axis_u × axis_v is the launch axis.
///
/// `diamond` turns the mesh by 45° about n: the net is the square net rotated by 45°, so its
/// threads run at ±45° to axis_u and axis_v (along d_u = (u + v)/√2 and d_v = (v − u)/√2), its
/// outline is a square of side s = side_u = side_v whose diagonals lie along the axes, and its
/// corners sit at center − (s/√2) v, center + (s/√2) u, center + (s/√2) v, center − (s/√2) u
/// (in perimeter order): a square net seen with its threads at 45° to the launcher's axes, the
/// "diamond mesh" of fishing-net terminology (ISO 1107).
struct GridNetSpec {
  double side_u = 1.0;  ///< side along axis_u (m), > 0
  double side_v = 1.0;  ///< side along axis_v (m), > 0
  int meshes_u = 1;     ///< meshes along axis_u, ≥ 1 (see MeshesForSize)
  int meshes_v = 1;     ///< meshes along axis_v, ≥ 1
  Vector3d center = Vector3d::Zero();
  Vector3d axis_u = Vector3d::UnitX();
  Vector3d axis_v = Vector3d::UnitY();
  bool diamond = false;
};

/// Knots on the (n_u + 1) × (n_v + 1) grid, numbered row by row: knot (i, j), the i-th along u
/// and the j-th along v, has index i + (n_u + 1) j and lies at
///   center + side_u (i/n_u − ½) d_u + side_v (j/n_v − ½) d_v
/// with (d_u, d_v) = (axis_u, axis_v), or the axes turned by 45° for a diamond net. Threads run
/// along both grid directions, n_u (n_v + 1) + n_v (n_u + 1) of them: first the n_u (n_v + 1)
/// along d_u, row by row, then the n_v (n_u + 1) along d_v, column by column. Every thread has
/// length side_u / n_u or side_v / n_v.
/// The perimeter has 2 (n_u + n_v) knots, counter-clockwise about n from the corner (0, 0); the
/// corners are (0, 0), (n_u, 0), (n_u, n_v), (0, n_v).
/// axis_u and axis_v may be off a unit orthogonal pair by 1e-6 (a scene file's 7 digits); they
/// are then made exactly orthonormal (Gram–Schmidt, keeping the direction of axis_u).
/// Throws InputError for a side ≤ 0, fewer than 1 mesh per side, axes that are not orthogonal
/// unit vectors, a non-finite centre, or a diamond net with unequal sides.
NetTopology MakeGridNet(const GridNetSpec& spec);

/// Meshes along a side of length `side` for a mesh size (both m, > 0): round(side / mesh_size),
/// at least 1. Throws InputError for values that are not positive and finite, or more than a
/// million meshes.
int MeshesForSize(double side, double mesh_size);

/// A net given as an explicit graph, validated: at least 2 finite knots and 1 thread; each thread
/// joins two different knots in range, at distinct positions, and appears once (in either
/// direction); a perimeter, when given, lists at least 3 different knots in range; each corner
/// is a different perimeter knot. Throws InputError naming the first fault.
NetTopology MakeGraphNet(std::vector<Vector3d> knots, std::vector<std::array<Index, 2>> threads,
                         std::vector<Index> perimeter = {}, std::vector<Index> corners = {});

}  // namespace ancfnet
