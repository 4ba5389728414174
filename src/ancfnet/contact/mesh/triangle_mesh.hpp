#pragma once
/// @file A triangle mesh (the surface of a rigid contact target: a spacecraft body, an antenna
/// dish), read from STL, OBJ or PLY through assimp, and placed in the world at load time.

#include <filesystem>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Vertices and triangles of a surface. A closed mesh has its triangles counter-clockwise seen
/// from outside (MeshBvh reorients a closed mesh whose enclosed volume comes out negative).
struct TriangleMesh {
  Eigen::Matrix3Xd vertices;   ///< columns: vertex positions (m)
  Eigen::Matrix3Xi triangles;  ///< columns: the three vertex indices of each triangle
};

/// Reads the triangles of every mesh in the file `path` (any format assimp reads: STL ASCII or
/// binary, OBJ, PLY, …), with aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
/// aiProcess_PreTransformVertices, then welds vertices at identical positions (STL stores each
/// facet's corners apart, and assimp keeps them apart where the facet normals differ) and drops
/// triangles with a repeated vertex, so that neighbouring triangles share their edges. Lines and
/// points in the file are ignored. Throws InputError naming the file when it does not exist,
/// cannot be read, holds no triangle or has a non-finite coordinate.
TriangleMesh LoadTriangleMesh(const std::filesystem::path& path);

/// Places a mesh given in its own frame M in the world: x_W = p_WM + R_WM (s x_M), with the
/// scale s > 0 and the rotation R_WM (preconditions, not checked).
void TransformTriangleMesh(double scale, const Matrix3d& R_WM, const Vector3d& p_WM,
                           TriangleMesh* mesh);

}  // namespace ancfnet
