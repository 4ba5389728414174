#include "ancfnet/contact/mesh/triangle_mesh.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include <array>
#include <assimp/Importer.hpp>
#include <cmath>
#include <map>
#include <vector>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

TriangleMesh LoadTriangleMesh(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(fmt::format("{}: cannot open mesh file (no such file)", path.string()));
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_PreTransformVertices);
  if (scene == nullptr)
    throw InputError(
        fmt::format("{}: cannot read mesh file: {}", path.string(), importer.GetErrorString()));
  // Weld by exact position: index of each distinct position.
  std::map<std::array<double, 3>, int> index_of;
  std::vector<Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    std::vector<int> welded(mesh.mNumVertices);
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
      const aiVector3D& v = mesh.mVertices[i];
      const std::array<double, 3> key{v.x, v.y, v.z};
      if (!std::isfinite(key[0]) || !std::isfinite(key[1]) || !std::isfinite(key[2]))
        throw InputError(fmt::format("{}: a vertex coordinate is not finite", path.string()));
      const auto [it, inserted] = index_of.try_emplace(key, static_cast<int>(vertices.size()));
      if (inserted) vertices.emplace_back(key[0], key[1], key[2]);
      welded[i] = it->second;
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      const Eigen::Vector3i t(welded[face.mIndices[0]], welded[face.mIndices[1]],
                              welded[face.mIndices[2]]);
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
      triangles.push_back(t);
    }
  }
  if (triangles.empty())
    throw InputError(fmt::format("{}: the mesh file holds no triangle", path.string()));
  TriangleMesh out;
  out.vertices.resize(3, static_cast<Index>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i) out.vertices.col(i) = vertices[i];
  out.triangles.resize(3, static_cast<Index>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i) out.triangles.col(i) = triangles[i];
  return out;
}

void TransformTriangleMesh(double scale, const Matrix3d& R_WM, const Vector3d& p_WM,
                           TriangleMesh* mesh) {
  mesh->vertices = ((scale * R_WM) * mesh->vertices).colwise() + p_WM;
}

}  // namespace ancfnet
