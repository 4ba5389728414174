// Scene files with capsule and mesh contact targets: the keys read into the model, the mesh file
// found beside the scene file, and bad input reported with file, line and key.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

// tests/data (CTest sets ANCFNET_SOURCE_DIR; by hand, run from the repository's root).
std::filesystem::path DataDir() {
  const char* dir = std::getenv("ANCFNET_SOURCE_DIR");
  return (dir != nullptr ? std::filesystem::path(dir) : std::filesystem::current_path()) / "tests" /
         "data";
}

TEST(MeshTargetScene, ReadsTheMeshBesideTheSceneFileAndTheCapsule) {
  const Scene scene = LoadScene(DataDir() / "ball_on_mesh_box.yaml");
  const auto& targets = scene.model.contact().targets;
  ASSERT_EQ(targets.size(), 2u);
  ASSERT_EQ(targets[0].kind, ContactTarget::Kind::kMesh);
  const MeshBvh& box = *targets[0].mesh;
  EXPECT_TRUE(box.closed());
  EXPECT_NEAR(box.normals().volume, 0.008, 1e-15);
  // Scaled by 0.2, turned by 90° about z (a corner (x, y) goes to (−y, x)), moved down 0.1 m.
  const Eigen::Vector3d lower = box.mesh().vertices.rowwise().minCoeff();
  const Eigen::Vector3d upper = box.mesh().vertices.rowwise().maxCoeff();
  EXPECT_TRUE(lower.isApprox(Vector3d(-0.1, -0.1, -0.2), 1e-14));
  EXPECT_TRUE(upper.isApprox(Vector3d(0.1, 0.1, 0.0), 1e-14));
  const MeshDistance above = box.CalcDistance(Vector3d(0.03, -0.02, 0.05));
  EXPECT_NEAR(above.distance, 0.05, 1e-15);
  EXPECT_TRUE(above.normal.isApprox(Vector3d::UnitZ(), 1e-14));
  const ContactTarget& strut = targets[1];
  EXPECT_EQ(strut.kind, ContactTarget::Kind::kCapsule);
  EXPECT_EQ(strut.normal, Vector3d::UnitY());
  EXPECT_DOUBLE_EQ(strut.radius, 0.05);
  EXPECT_DOUBLE_EQ(strut.half_length, 0.2);
}

// The message of the InputError from parsing the scene (its mesh files taken from tests/data).
std::string SceneError(const std::string& targets) {
  const std::string yaml =
      "point_masses:\n  - {name: ball, mass: 0.1, position: [0, 0, 1]}\n"
      "contact:\n  law: {type: linear, stiffness: 1.0e4}\n  targets:\n" +
      targets;
  try {
    ParseScene(yaml, "scene.yaml", DataDir());
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(MeshTargetScene, BadInputNamesTheFileLineAndKey) {
  EXPECT_EQ(SceneError("    - {type: mesh, file: cube.stl}\n"),
            "scene.yaml:6:26: " + (DataDir() / "cube.stl").string() +
                ": cannot open mesh file (no such file) (key 'file')");
  EXPECT_EQ(SceneError("    - {type: mesh, file: unit_cube.stl, scale: 0}\n"),
            "scene.yaml:6:48: expected a number > 0, got '0' (key 'scale')");
  EXPECT_EQ(SceneError("    - {type: mesh, file: unit_cube.stl, rotation: {axis: [0, 0, 0], "
                       "angle: 3}}\n")
                .rfind("scene.yaml:6:", 0),
            0u);
  EXPECT_NE(SceneError("    - {type: mesh, file: unit_cube.stl, rotation: {angle: 3, turns: 1}}\n")
                .find("unknown key 'turns'"),
            std::string::npos);
  EXPECT_NE(SceneError("    - {type: capsule, center: [0, 0, 0], radius: 0.1, length: 1}\n")
                .find("'length'"),
            std::string::npos);
  EXPECT_NE(SceneError("    - {type: capsule, center: [0, 0, 0], radius: 0.1, half_length: -1}\n")
                .find("half_length"),
            std::string::npos);
}

}  // namespace
}  // namespace ancfnet
