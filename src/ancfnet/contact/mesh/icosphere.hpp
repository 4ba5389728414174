#pragma once
/// @file A sphere approximated by triangles: the icosahedron, each triangle split in four k times
/// with the new vertices pushed out onto the sphere (a faceted sphere target, a benchmark mesh).

#include "ancfnet/contact/mesh/triangle_mesh.hpp"

namespace ancfnet {

/// The icosphere of radius R (m) centred at the origin after k ≥ 0 subdivisions: 20·4ᵏ triangles
/// (counter-clockwise seen from outside) and 10·4ᵏ + 2 vertices, all on the sphere.
TriangleMesh MakeIcosphere(double radius, int subdivisions);

}  // namespace ancfnet
