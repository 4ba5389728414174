// Net designs: counts, mesh sizes, perimeter and corners of grid and diamond nets, and the
// validation of explicit graphs.

#include "ancfnet/model/net_topology.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ancfnet/analysis/net_metrics.hpp"
#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

std::vector<Vector3d> Perimeter(const NetTopology& net) {
  std::vector<Vector3d> polygon;
  for (Index k : net.perimeter) polygon.push_back(net.knots[k]);
  return polygon;
}

TEST(NetTopology, GridNetHasTheRightCountsAndMeshes) {
  for (auto [nu, nv] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{10, 10}}) {
    const NetTopology net = MakeGridNet({.side_u = 3.0, .side_v = 2.0, .meshes_u = nu, .meshes_v = nv});
    EXPECT_EQ(net.knots.size(), static_cast<std::size_t>((nu + 1) * (nv + 1)));
    EXPECT_EQ(net.threads.size(), static_cast<std::size_t>(nu * (nv + 1) + nv * (nu + 1)));
    EXPECT_EQ(net.perimeter.size(), static_cast<std::size_t>(2 * (nu + nv)));
    ASSERT_EQ(net.corners.size(), 4u);
    for (const auto& [a, b] : net.threads) {
      const double length = (net.knots[a] - net.knots[b]).norm();
      EXPECT_TRUE(std::abs(length - 3.0 / nu) < 1e-12 || std::abs(length - 2.0 / nv) < 1e-12);
    }
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), Vector3d::UnitZ()), 6.0, 1e-12);
  }
}

TEST(NetTopology, TiltedAndDiamondNetsKeepTheirArea) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.8, Vector3d(1, 2, -1).normalized()).toRotationMatrix();
  const Vector3d u = rotation * Vector3d::UnitX(), v = rotation * Vector3d::UnitY();
  for (bool diamond : {false, true}) {
    const NetTopology net = MakeGridNet({.side_u = 2.0, .side_v = 2.0, .meshes_u = 4,
                                         .meshes_v = 4, .center = Vector3d(1, -2, 3),
                                         .axis_u = u, .axis_v = v, .diamond = diamond});
    const Vector3d normal = u.cross(v);
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), normal), 4.0, 1e-12);
    // Seen along an axis tilted by 60° from the normal, the area is A cos 60°.
    const Vector3d tilted = std::cos(M_PI / 3) * normal + std::sin(M_PI / 3) * u;
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), tilted), 2.0, 1e-12);
  }
  // A diamond net's corners point along the axes.
  const NetTopology diamond = MakeGridNet({.side_u = 2.0, .side_v = 2.0, .meshes_u = 2,
                                           .meshes_v = 2, .diamond = true});
  EXPECT_NEAR(diamond.knots[diamond.corners[0]].y(), -std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(diamond.knots[diamond.corners[0]].x(), 0.0, 1e-12);
}

TEST(NetTopology, RejectsInvalidDesigns) {
  EXPECT_THROW(MakeGridNet({.side_u = 0.0}), InputError);
  EXPECT_THROW(MakeGridNet({.meshes_u = 0}), InputError);
  EXPECT_THROW(MakeGridNet({.axis_v = Vector3d(1, 1, 0)}), InputError);
  const std::vector<Vector3d> knots = {Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY()};
  EXPECT_NO_THROW(MakeGraphNet(knots, {{0, 1}, {1, 2}}));
  EXPECT_THROW(MakeGraphNet(knots, {{0, 3}}), InputError);
  EXPECT_THROW(MakeGraphNet(knots, {{1, 1}}), InputError);
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}, {1, 0}}), InputError);
  EXPECT_THROW(MakeGraphNet({Vector3d::Zero(), Vector3d::Zero()}, {{0, 1}}), InputError);
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {0, 5}), InputError);
  EXPECT_EQ(MeshesForSize(5.0, 0.45), 11);
}

TEST(NetMetrics, AreaOfANonConvexPolygonAndCentroid) {
  // An L-shaped hexagon of area 3 in the plane z = 1.
  const std::vector<Vector3d> l_shape = {{0, 0, 1}, {2, 0, 1}, {2, 1, 1},
                                         {1, 1, 1}, {1, 2, 1}, {0, 2, 1}};
  EXPECT_NEAR(CalcMouthArea(l_shape, Vector3d(0, 0, -2)), 3.0, 1e-12);
  const Vector3d c = CalcCentroid({{0, 0, 0}, {4, 0, 0}}, {3.0, 1.0});
  EXPECT_TRUE(c.isApprox(Vector3d(1, 0, 0)));
}

}  // namespace
}  // namespace ancfnet
