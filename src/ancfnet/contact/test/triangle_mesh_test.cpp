#include "ancfnet/contact/mesh/triangle_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/mesh/mesh_normals.hpp"
#include "ancfnet/contact/test/mesh_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::MeshDataDir;

TEST(TriangleMesh, LoadsTheUnitCubeFromAsciiStl) {
  const TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "unit_cube.stl");
  EXPECT_EQ(mesh.vertices.cols(), 8);  // welded: STL stores 36 corners
  EXPECT_EQ(mesh.triangles.cols(), 12);
  EXPECT_TRUE(mesh.vertices.cwiseAbs().isApproxToConstant(0.5, 1e-15));
  const MeshNormals normals = CalcMeshNormals(mesh);
  EXPECT_TRUE(normals.closed);
  EXPECT_EQ(normals.edge.cols(), 18);  // 12 of the cube, 6 diagonals
  EXPECT_NEAR(normals.volume, 1.0, 1e-15);
  // A corner's pseudo-normal is along the diagonal (the three right angles weigh alike).
  for (Index v = 0; v < 8; ++v) {
    const Vector3d corner = mesh.vertices.col(v);
    EXPECT_NEAR(normals.vertex.col(v).dot(corner.normalized()), 1.0, 1e-14);
  }
}

TEST(TriangleMesh, LoadsTheIcosahedronFromObj) {
  const TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "icosahedron.obj");
  EXPECT_EQ(mesh.vertices.cols(), 12);
  EXPECT_EQ(mesh.triangles.cols(), 20);
  for (Index v = 0; v < 12; ++v) EXPECT_NEAR(mesh.vertices.col(v).norm(), 1.0, 1e-7);
  const MeshNormals normals = CalcMeshNormals(mesh);
  EXPECT_TRUE(normals.closed);
  // Edge a = 4R/√(10 + 2√5), volume (5/12)(3 + √5) a³ (the vertices are stored in single
  // precision by assimp: 1e-6).
  const double a = 4.0 / std::sqrt(10.0 + 2.0 * std::sqrt(5.0));
  EXPECT_NEAR(normals.volume, 5.0 / 12.0 * (3.0 + std::sqrt(5.0)) * a * a * a, 1e-6);
}

TEST(TriangleMesh, LoadsTheTetrahedronFromPly) {
  const TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "tetrahedron.ply");
  EXPECT_EQ(mesh.vertices.cols(), 4);
  EXPECT_EQ(mesh.triangles.cols(), 4);
  const MeshNormals normals = CalcMeshNormals(mesh);
  EXPECT_TRUE(normals.closed);
  EXPECT_NEAR(normals.volume, 1.0 / 6.0, 1e-15);
}

TEST(TriangleMesh, AnOpenSheetIsNotClosed) {
  const TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "square_sheet.obj");
  EXPECT_EQ(mesh.triangles.cols(), 2);
  const MeshNormals normals = CalcMeshNormals(mesh);
  EXPECT_FALSE(normals.closed);
  for (Index v = 0; v < 4; ++v) EXPECT_TRUE(normals.vertex.col(v).isApprox(Vector3d::UnitZ()));
}

TEST(TriangleMesh, TransformScalesRotatesAndMoves) {
  TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "tetrahedron.ply");
  const Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vector3d p(1, -2, 3);
  TransformTriangleMesh(2.0, R, p, &mesh);
  EXPECT_TRUE(mesh.vertices.col(0).isApprox(p, 1e-15));
  EXPECT_TRUE(mesh.vertices.col(3).isApprox(p + 2.0 * R.col(2), 1e-15));
  EXPECT_NEAR(CalcMeshNormals(mesh).volume, 8.0 / 6.0, 1e-14);
}

TEST(TriangleMesh, IcosphereCounts) {
  for (int k = 0; k < 4; ++k) {
    const TriangleMesh mesh = MakeIcosphere(0.5, k);
    const int scale = 1 << (2 * k);
    EXPECT_EQ(mesh.triangles.cols(), 20 * scale);
    EXPECT_EQ(mesh.vertices.cols(), 10 * scale + 2);
    const MeshNormals normals = CalcMeshNormals(mesh);
    EXPECT_TRUE(normals.closed);
    // Inside the sphere, approaching (4/3)π R³ from below.
    EXPECT_GT(normals.volume, 0.0);
    EXPECT_LT(normals.volume, 4.0 / 3.0 * std::numbers::pi * 0.125);
  }
  EXPECT_NEAR(CalcMeshNormals(MakeIcosphere(0.5, 4)).volume / (std::numbers::pi / 6.0), 1.0, 5e-3);
}

// The message of the InputError thrown by loading `path`, or "" if none is.
std::string LoadError(const std::filesystem::path& path) {
  try {
    LoadTriangleMesh(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(TriangleMesh, BadFilesGiveAClearError) {
  const std::filesystem::path missing = MeshDataDir() / "no_such_mesh.stl";
  EXPECT_EQ(LoadError(missing), missing.string() + ": cannot open mesh file (no such file)");
  EXPECT_EQ(LoadError(MeshDataDir()).find("cannot open mesh file"),
            MeshDataDir().string().size() + 2);  // a folder
  const std::filesystem::path empty = MeshDataDir() / "points_only.obj";
  const std::string message = LoadError(empty);
  EXPECT_EQ(message.rfind(empty.string() + ": ", 0), 0u) << message;
  // Not a mesh at all: assimp's own reason follows.
  const std::filesystem::path text = MeshDataDir().parent_path() / "CMakeLists.txt";
  const std::string unreadable = LoadError(text);
  EXPECT_EQ(unreadable.rfind(text.string() + ": cannot read mesh file: ", 0), 0u) << unreadable;
}

}  // namespace
}  // namespace ancfnet
