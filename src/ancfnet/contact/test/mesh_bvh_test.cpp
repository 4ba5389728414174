#include "ancfnet/contact/mesh/mesh_bvh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "ancfnet/contact/distance/point_box.hpp"
#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/test/distance_test_helpers.hpp"
#include "ancfnet/contact/test/mesh_test_helpers.hpp"

namespace ancfnet {
namespace {

using test::CheckGradientAndHessian;
using test::MeshDataDir;
using test::RandomRotation;
using test::RandomVector;

// Inside a convex polyhedron iff behind every face plane: a sign independent of the
// pseudo-normals.
bool InsideConvex(const MeshBvh& bvh, const Vector3d& p) {
  const TriangleMesh& mesh = bvh.mesh();
  for (Index t = 0; t < mesh.triangles.cols(); ++t)
    if ((p - mesh.vertices.col(mesh.triangles(0, t))).dot(bvh.normals().face.col(t)) > 0.0)
      return false;
  return true;
}

// A closed, non-convex mesh: an icosphere (320 triangles) whose vertices are pushed in and out
// at random, star-shaped about the origin, with concave edges and vertices.
TriangleMesh BumpySphere() {
  TriangleMesh mesh = MakeIcosphere(1.0, 2);
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.7, 1.3);
  for (Index v = 0; v < mesh.vertices.cols(); ++v) mesh.vertices.col(v) *= u(rng);
  return mesh;
}

// Inside iff a ray from p crosses the surface an odd number of times (ray–triangle test of
// Möller & Trumbore 1997): a sign independent of the pseudo-normals for any closed mesh.
bool InsideByRayParity(const TriangleMesh& mesh, const Vector3d& p) {
  const Vector3d dir = Vector3d(0.3127, 0.5711, 0.7594).normalized();
  int crossings = 0;
  for (Index t = 0; t < mesh.triangles.cols(); ++t) {
    const Vector3d a = mesh.vertices.col(mesh.triangles(0, t));
    const Vector3d e1 = mesh.vertices.col(mesh.triangles(1, t)) - a;
    const Vector3d e2 = mesh.vertices.col(mesh.triangles(2, t)) - a;
    const Vector3d h = dir.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-14) continue;
    const Vector3d s = p - a;
    const double u = s.dot(h) / det;
    const Vector3d q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
    crossings += e2.dot(q) / det > 0.0;
  }
  return crossings % 2 == 1;
}

// The BVH descent finds the same closest point as testing every triangle, and its |φ| is the
// least point–triangle distance.
void CheckAgainstBruteForce(const MeshBvh& bvh, double extent, bool convex, unsigned seed) {
  std::mt19937 rng(seed);
  int inside = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vector3d p = RandomVector(&rng, -extent, extent);
    const MeshDistance fast = bvh.CalcDistance(p);
    const MeshDistance slow = bvh.CalcDistanceBruteForce(p);
    double least = std::numeric_limits<double>::infinity();
    const TriangleMesh& m = bvh.mesh();
    for (Index t = 0; t < m.triangles.cols(); ++t)
      least = std::min(least, CalcPointTriangleDistance(p, m.vertices.col(m.triangles(0, t)),
                                                        m.vertices.col(m.triangles(1, t)),
                                                        m.vertices.col(m.triangles(2, t)))
                                  .distance);
    ASSERT_NEAR(std::abs(fast.distance), least, 1e-15 * (1.0 + least));
    ASSERT_NEAR(fast.distance, slow.distance, 1e-15 * (1.0 + least));
    ASSERT_LT((fast.closest_point - slow.closest_point).norm(), 1e-12);
    ASSERT_LT((fast.normal - slow.normal).norm(), 1e-12);
    if (convex) {
      ASSERT_EQ(fast.distance < 0.0, InsideConvex(bvh, p)) << p.transpose();
      inside += fast.distance < 0.0;
    }
  }
  if (convex) {
    EXPECT_GT(inside, 10);
  }
}

TEST(MeshBvh, ClosestPointEqualsBruteForce) {
  const MeshBvh sphere(MakeIcosphere(1.0, 3));  // 1280 triangles
  EXPECT_TRUE(sphere.closed());
  EXPECT_LE(sphere.depth(), static_cast<int>(std::ceil(std::log2(1280 / 4.0))) + 1);
  CheckAgainstBruteForce(sphere, 1.6, true, 71);
  CheckAgainstBruteForce(MeshBvh(LoadTriangleMesh(MeshDataDir() / "unit_cube.stl")), 1.0, true, 72);
  CheckAgainstBruteForce(MeshBvh(LoadTriangleMesh(MeshDataDir() / "tetrahedron.ply")), 1.5, true,
                         73);
  CheckAgainstBruteForce(MeshBvh(BumpySphere()), 1.6, false, 78);
  const MeshBvh sheet(LoadTriangleMesh(MeshDataDir() / "square_sheet.obj"));
  EXPECT_FALSE(sheet.closed());
  CheckAgainstBruteForce(sheet, 1.5, false, 74);
}

// The pseudo-normal sign on a non-convex closed mesh, where the closest feature of inside points
// is often a concave edge or vertex (Bærentzen & Aanæs 2005), against ray parity.
TEST(MeshBvh, SignOfANonConvexMeshMatchesRayParity) {
  const MeshBvh bumpy(BumpySphere());
  ASSERT_TRUE(bumpy.closed());
  std::mt19937 rng(79);
  int inside = 0, inside_at_edges_or_vertices = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vector3d p = RandomVector(&rng, -1.4, 1.4);
    const MeshDistance d = bumpy.CalcDistance(p);
    if (std::abs(d.distance) < 1e-9) continue;
    ASSERT_EQ(d.distance < 0.0, InsideByRayParity(bumpy.mesh(), p)) << p.transpose();
    inside += d.distance < 0.0;
    inside_at_edges_or_vertices += d.distance < 0.0 && d.feature != MeshFeature::kFace;
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(inside_at_edges_or_vertices, 50);
  std::cout << "[measured] bumpy sphere: sign = ray parity at 3000 points (" << inside
            << " inside, " << inside_at_edges_or_vertices
            << " of them nearest an edge or vertex)\n";
}

// A cube mesh, scaled, turned and moved, against the analytical box: the same signed distance,
// normal and Hessian outside (faces, edges, corners) and inside (away from the planes where two
// faces are equally near and the box's normal jumps).
TEST(MeshBvh, CubeMeshMatchesTheBox) {
  std::mt19937 rng(75);
  const Matrix3d R = RandomRotation(&rng);
  const Vector3d c(0.3, -0.2, 0.1);
  const double side = 0.8;
  TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "unit_cube.stl");
  TransformTriangleMesh(side, R, c, &mesh);
  const MeshBvh cube(std::move(mesh));
  const Vector3d h = Vector3d::Constant(side / 2);
  int inside = 0, outside = 0;
  double worst = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const Vector3d p = c + RandomVector(&rng, -1.0, 1.0);
    const PointBoxDistance box = CalcPointBoxDistance(p, c, h, R);
    const MeshDistance d = cube.CalcDistance(p);
    if (box.inside) {
      Vector3d depth = h - (R.transpose() * (p - c)).cwiseAbs();
      std::sort(depth.data(), depth.data() + 3);
      if (depth[1] - depth[0] < 1e-6) continue;
      ++inside;
    } else {
      ++outside;
      EXPECT_LT((d.hessian - box.hessian).norm(), 1e-9 * (1.0 + box.hessian.norm()));
    }
    EXPECT_NEAR(d.distance, box.distance, 1e-14);
    EXPECT_LT((d.normal - box.normal).norm(), 1e-9);
    worst = std::max(worst, std::abs(d.distance - box.distance));
  }
  EXPECT_GT(inside, 150);
  EXPECT_GT(outside, 1000);
  std::cout << "[measured] cube mesh vs box: |Δφ| max " << worst << " (" << inside << " inside, "
            << outside << " outside)\n";
}

// ∂φ/∂p = n and ∂n/∂p = Hessian by central differences, on a closed faceted sphere, a closed
// non-convex mesh and an open sheet, skipping points whose perturbations change the closest
// feature.
TEST(MeshBvh, GradientAndHessianMatchFiniteDifferences) {
  const MeshBvh sphere(MakeIcosphere(1.0, 2));
  const MeshBvh bumpy(BumpySphere());
  const MeshBvh sheet(LoadTriangleMesh(MeshDataDir() / "square_sheet.obj"));
  std::mt19937 rng(76);
  for (const MeshBvh* bvh : {&sphere, &bumpy, &sheet}) {
    double worst_g = 0.0, worst_h = 0.0;
    int checked = 0, edges_and_vertices = 0;
    for (int k = 0; k < 600; ++k) {
      const Vector3d p = RandomVector(&rng, -1.6, 1.6);
      auto eval = [&](const Vector3d& x) { return bvh->CalcDistance(x); };
      auto key = [&](const Vector3d& x) {
        const MeshDistance d = eval(x);
        return 10 * d.feature_index + static_cast<int>(d.feature);
      };
      const int before = checked;
      CheckGradientAndHessian(eval, key, p, &worst_g, &worst_h, &checked);
      edges_and_vertices += checked > before && eval(p).feature != MeshFeature::kFace;
    }
    EXPECT_GT(checked, 400);
    EXPECT_GT(edges_and_vertices, 100);
    std::cout << "[measured] mesh (" << bvh->mesh().triangles.cols() << " triangles, "
              << (bvh->closed() ? "closed" : "open") << "): gradient FD error " << worst_g
              << ", Hessian " << worst_h << " over " << checked << " (" << edges_and_vertices
              << " at edges or vertices)\n";
  }
}

// An open sheet repels from both sides: a point behind it is pushed back behind, not through.
TEST(MeshBvh, OpenSheetIsTwoSided) {
  const MeshBvh sheet(LoadTriangleMesh(MeshDataDir() / "square_sheet.obj"));
  const MeshDistance above = sheet.CalcDistance(Vector3d(0.2, 0.1, 0.05));
  EXPECT_DOUBLE_EQ(above.distance, 0.05);
  EXPECT_TRUE(above.normal.isApprox(Vector3d::UnitZ()));
  EXPECT_TRUE(above.hessian.isZero());
  const MeshDistance below = sheet.CalcDistance(Vector3d(0.2, 0.1, -0.05));
  EXPECT_DOUBLE_EQ(below.distance, 0.05);
  EXPECT_TRUE(below.normal.isApprox(-Vector3d::UnitZ()));
  // Past the rim: the distance to the boundary edge x = 1, normal from the edge to the point.
  const MeshDistance rim = sheet.CalcDistance(Vector3d(1.3, 0.2, -0.4));
  EXPECT_EQ(rim.feature, MeshFeature::kEdge);
  EXPECT_DOUBLE_EQ(rim.distance, 0.5);
  EXPECT_TRUE(rim.normal.isApprox(Vector3d(0.6, 0, -0.8)));
  // On the sheet (to rounding): a normal of the sheet, the side left to the rounding.
  const MeshDistance on = sheet.CalcDistance(Vector3d(0.2, 0.1, 0.0));
  EXPECT_LT(on.distance, 1e-15);
  EXPECT_NEAR(std::abs(on.normal.z()), 1.0, 1e-15);
}

// A point that is not finite (a diverging Newton iterate) gives no contact, and no crash.
TEST(MeshBvh, NonFinitePointGivesNaNDistance) {
  const MeshBvh sphere(MakeIcosphere(1.0, 1));
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const MeshDistance d = sphere.CalcDistance(Vector3d(0.1, bad, 0.2));
    EXPECT_TRUE(std::isnan(d.distance));
    EXPECT_EQ(d.triangle, -1);
    EXPECT_TRUE(d.normal.allFinite() && d.hessian.allFinite());
  }
}

// A closed mesh written clockwise (seen from outside) is turned the right way round.
TEST(MeshBvh, InsideOutClosedMeshIsReoriented) {
  TriangleMesh mesh = LoadTriangleMesh(MeshDataDir() / "tetrahedron.ply");
  mesh.triangles.row(0).swap(mesh.triangles.row(1));
  const MeshBvh bvh(std::move(mesh));
  EXPECT_TRUE(bvh.closed());
  EXPECT_NEAR(bvh.normals().volume, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(bvh.CalcDistance(Vector3d(0.1, 0.1, 0.1)).distance, -0.1, 1e-15);
  EXPECT_NEAR(bvh.CalcDistance(Vector3d(0.1, 0.1, -0.3)).distance, 0.3, 1e-15);
}

}  // namespace
}  // namespace ancfnet
