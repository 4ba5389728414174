// Net designs: counts, numbering, mesh sizes, perimeter and corners of grid and diamond nets in
// any orientation, and the validation of grid specs and explicit graphs.

#include "ancfnet/model/net_topology.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "ancfnet/analysis/net_metrics.hpp"
#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

constexpr double kTol = 1e-12;

std::vector<Vector3d> Perimeter(const NetTopology& net) {
  std::vector<Vector3d> polygon;
  for (Index k : net.perimeter) polygon.push_back(net.knots[k]);
  return polygon;
}

std::set<std::pair<Index, Index>> ThreadSet(const NetTopology& net) {
  std::set<std::pair<Index, Index>> set;
  for (const auto& [a, b] : net.threads) set.insert({std::min(a, b), std::max(a, b)});
  return set;
}

// The perimeter is a closed loop of distinct knots, each joined to the next (and the last to
// the first) by a thread, and the corners appear on it in order.
void ExpectClosedPerimeter(const NetTopology& net) {
  const auto threads = ThreadSet(net);
  const std::size_t n = net.perimeter.size();
  EXPECT_EQ(std::set<Index>(net.perimeter.begin(), net.perimeter.end()).size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const Index a = net.perimeter[i], b = net.perimeter[(i + 1) % n];
    EXPECT_TRUE(threads.contains({std::min(a, b), std::max(a, b)}))
        << "perimeter knots " << a << " and " << b << " are not joined";
  }
  std::ptrdiff_t last = -1;
  for (Index corner : net.corners) {
    const auto it = std::find(net.perimeter.begin(), net.perimeter.end(), corner);
    ASSERT_NE(it, net.perimeter.end());
    EXPECT_GT(it - net.perimeter.begin(), last);
    last = it - net.perimeter.begin();
  }
}

// A rotation taking the world axes to an arbitrary orientation.
Matrix3d ArbitraryRotation() {
  return Eigen::AngleAxisd(0.8, Vector3d(1, 2, -1).normalized()).toRotationMatrix();
}

TEST(NetTopology, GridNetHasTheRightCountsMeshesAndNumbering) {
  for (auto [nu, nv] : {std::pair{1, 1}, std::pair{1, 4}, std::pair{3, 2}, std::pair{10, 10}}) {
    const NetTopology net =
        MakeGridNet({.side_u = 3.0, .side_v = 2.0, .meshes_u = nu, .meshes_v = nv});
    EXPECT_EQ(net.knots.size(), static_cast<std::size_t>((nu + 1) * (nv + 1)));
    EXPECT_EQ(net.threads.size(), static_cast<std::size_t>(nu * (nv + 1) + nv * (nu + 1)));
    EXPECT_EQ(ThreadSet(net).size(), net.threads.size());
    EXPECT_EQ(net.perimeter.size(), static_cast<std::size_t>(2 * (nu + nv)));
    ASSERT_EQ(net.corners.size(), 4u);
    // Row-major numbering: knot (i, j) has index i + (nu + 1) j.
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i)
        EXPECT_TRUE(net.knots[i + (nu + 1) * j].isApprox(
            Vector3d(3.0 * i / nu - 1.5, 2.0 * j / nv - 1.0, 0.0), kTol));
    // The first nu (nv + 1) threads run along u, the others along v, each one mesh long.
    for (std::size_t t = 0; t < net.threads.size(); ++t) {
      const Vector3d d = net.knots[net.threads[t][1]] - net.knots[net.threads[t][0]];
      const bool along_u = t < static_cast<std::size_t>(nu * (nv + 1));
      EXPECT_TRUE(d.isApprox(along_u ? Vector3d(3.0 / nu, 0, 0) : Vector3d(0, 2.0 / nv, 0), kTol));
    }
    ExpectClosedPerimeter(net);
    EXPECT_EQ(net.corners, (std::vector<Index>{0, nu, (nu + 1) * (nv + 1) - 1, (nu + 1) * nv}));
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), Vector3d::UnitZ()), 6.0, kTol);
    EXPECT_TRUE(CalcCentroid(net.knots).isZero(kTol));
  }
}

TEST(NetTopology, GridNetInAnyOrientationKeepsItsAreaAndProjects) {
  const Matrix3d rotation = ArbitraryRotation();
  const Vector3d u = rotation.col(0), v = rotation.col(1), normal = rotation.col(2);
  const Vector3d center(1, -2, 3);
  const NetTopology net = MakeGridNet({.side_u = 3.0,
                                       .side_v = 1.5,
                                       .meshes_u = 6,
                                       .meshes_v = 3,
                                       .center = center,
                                       .axis_u = u,
                                       .axis_v = v});
  EXPECT_TRUE(CalcCentroid(net.knots).isApprox(center, kTol));
  for (const Vector3d& knot : net.knots) EXPECT_NEAR((knot - center).dot(normal), 0.0, kTol);
  for (const auto& [a, b] : net.threads)
    EXPECT_NEAR((net.knots[a] - net.knots[b]).norm(), 0.5, kTol);
  EXPECT_NEAR(CalcMouthArea(Perimeter(net), normal), 4.5, kTol);
  EXPECT_NEAR(CalcMouthArea(Perimeter(net), -normal), 4.5, kTol);
  // Seen along an axis tilted by θ from the normal, the area is A |cos θ|.
  for (double theta : {0.3, std::numbers::pi / 3, 2.0, std::numbers::pi / 2}) {
    const Vector3d tilted = std::cos(theta) * normal + std::sin(theta) * (u + 2 * v).normalized();
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), tilted), 4.5 * std::abs(std::cos(theta)), kTol);
  }
  // The perimeter runs counter-clockwise about u × v.
  const std::vector<Vector3d> polygon = Perimeter(net);
  Vector3d twice_area = Vector3d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    twice_area += polygon[i].cross(polygon[(i + 1) % polygon.size()]);
  EXPECT_NEAR(twice_area.dot(normal), 9.0, 1e-10);
}

TEST(NetTopology, DiamondNetIsTheSquareNetTurnedBy45Degrees) {
  const Matrix3d rotation = ArbitraryRotation();
  const Vector3d u = rotation.col(0), v = rotation.col(1), normal = rotation.col(2);
  const Vector3d center(1, -2, 3);
  const double s = 2.0, half_diagonal = s / std::numbers::sqrt2;
  for (int n : {1, 2, 5}) {
    const NetTopology net = MakeGridNet({.side_u = s,
                                         .side_v = s,
                                         .meshes_u = n,
                                         .meshes_v = n,
                                         .center = center,
                                         .axis_u = u,
                                         .axis_v = v,
                                         .diamond = true});
    EXPECT_EQ(net.knots.size(), static_cast<std::size_t>((n + 1) * (n + 1)));
    EXPECT_EQ(net.threads.size(), static_cast<std::size_t>(2 * n * (n + 1)));
    EXPECT_EQ(net.perimeter.size(), static_cast<std::size_t>(4 * n));
    ExpectClosedPerimeter(net);
    // Threads are one mesh long, in the plane, at 45° to both axes.
    for (const auto& [a, b] : net.threads) {
      const Vector3d d = net.knots[b] - net.knots[a];
      EXPECT_NEAR(d.norm(), s / n, kTol);
      EXPECT_NEAR(d.dot(normal), 0.0, kTol);
      EXPECT_NEAR(std::abs(d.dot(u)), d.norm() / std::numbers::sqrt2, kTol);
      EXPECT_NEAR(std::abs(d.dot(v)), d.norm() / std::numbers::sqrt2, kTol);
    }
    // Corners point along −v, +u, +v, −u, in perimeter order.
    ASSERT_EQ(net.corners.size(), 4u);
    const Vector3d expected[] = {-v, u, v, -u};
    for (int c = 0; c < 4; ++c)
      EXPECT_TRUE(net.knots[net.corners[c]].isApprox(center + half_diagonal * expected[c], kTol));
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), normal), s * s, kTol);
    EXPECT_NEAR(CalcMouthArea(Perimeter(net), std::cos(1.0) * normal + std::sin(1.0) * u),
                s * s * std::cos(1.0), kTol);
  }
}

TEST(NetTopology, MeshesForSizeRoundsToTheNearestCountOfAtLeastOne) {
  EXPECT_EQ(MeshesForSize(5.0, 0.45), 11);  // 11.1
  EXPECT_EQ(MeshesForSize(5.0, 2.0), 3);    // 2.5 rounds away from zero
  EXPECT_EQ(MeshesForSize(1.0, 0.25), 4);
  EXPECT_EQ(MeshesForSize(1.0, 3.0), 1);  // 0.33 → still one mesh
  EXPECT_THROW(MeshesForSize(0.0, 0.1), InputError);
  EXPECT_THROW(MeshesForSize(1.0, -0.1), InputError);
  EXPECT_THROW(MeshesForSize(1.0, 0.0), InputError);
  EXPECT_THROW(MeshesForSize(std::nan(""), 0.1), InputError);
  EXPECT_THROW(MeshesForSize(1e9, 1e-3), InputError);
}

TEST(NetTopology, GridAxesWithinSceneFilePrecisionAreMadeOrthonormal) {
  const Vector3d u(0.7071068, 0.7071068, 0.0), v(-0.7071068, 0.7071068, 0.0);
  const NetTopology net = MakeGridNet({.meshes_u = 2, .meshes_v = 2, .axis_u = u, .axis_v = v});
  for (const auto& [a, b] : net.threads)
    EXPECT_NEAR((net.knots[a] - net.knots[b]).norm(), 0.5, kTol);
  EXPECT_NEAR(CalcMouthArea(Perimeter(net), Vector3d::UnitZ()), 1.0, kTol);
}

TEST(NetTopology, RejectsInvalidGridNets) {
  EXPECT_NO_THROW(MakeGridNet({}));
  EXPECT_THROW(MakeGridNet({.side_u = 0.0}), InputError);
  EXPECT_THROW(MakeGridNet({.side_v = -1.0}), InputError);
  EXPECT_THROW(MakeGridNet({.side_u = INFINITY}), InputError);
  EXPECT_THROW(MakeGridNet({.meshes_u = 0}), InputError);
  EXPECT_THROW(MakeGridNet({.meshes_v = -2}), InputError);
  EXPECT_THROW(MakeGridNet({.center = Vector3d(0, NAN, 0)}), InputError);
  EXPECT_THROW(MakeGridNet({.axis_u = Vector3d(2, 0, 0)}), InputError);               // not unit
  EXPECT_THROW(MakeGridNet({.axis_v = Vector3d::Zero()}), InputError);                // not unit
  EXPECT_THROW(MakeGridNet({.axis_v = Vector3d(1, 1, 0).normalized()}), InputError);  // not ⟂
  EXPECT_THROW(MakeGridNet({.axis_v = Vector3d::UnitX()}), InputError);               // parallel
  EXPECT_THROW(MakeGridNet({.side_u = 1.0, .side_v = 2.0, .diamond = true}), InputError);
  // The message is one line for the user.
  try {
    MakeGridNet({.axis_v = Vector3d(1, 1, 0).normalized()});
    FAIL();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("orthogonal"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(NetTopology, GraphNetKeepsAValidGraph) {
  // A unit square with one diagonal; the perimeter goes round it.
  const std::vector<Vector3d> knots = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const NetTopology net =
      MakeGraphNet(knots, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}, {0, 1, 2, 3}, {0, 2});
  EXPECT_EQ(net.knots, knots);
  EXPECT_EQ(net.threads.size(), 5u);
  EXPECT_EQ(net.corners, (std::vector<Index>{0, 2}));
  ExpectClosedPerimeter(net);
  EXPECT_NEAR(CalcMouthArea(Perimeter(net), Vector3d::UnitZ()), 1.0, kTol);
  EXPECT_TRUE(MakeGraphNet(knots, {{0, 1}}).perimeter.empty());
}

TEST(NetTopology, RejectsInvalidGraphNets) {
  const std::vector<Vector3d> knots = {Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY()};
  EXPECT_NO_THROW(MakeGraphNet(knots, {{0, 1}, {1, 2}}));
  EXPECT_THROW(MakeGraphNet({Vector3d::Zero()}, {}), InputError);  // 1 knot
  EXPECT_THROW(MakeGraphNet(knots, {}), InputError);               // no thread
  EXPECT_THROW(MakeGraphNet({Vector3d::Zero(), Vector3d(NAN, 0, 0)}, {{0, 1}}), InputError);
  EXPECT_THROW(MakeGraphNet(knots, {{0, 3}}), InputError);          // range
  EXPECT_THROW(MakeGraphNet(knots, {{-1, 2}}), InputError);         // range
  EXPECT_THROW(MakeGraphNet(knots, {{1, 1}}), InputError);          // self
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}, {1, 0}}), InputError);  // repeated
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}, {0, 1}}), InputError);  // repeated
  EXPECT_THROW(MakeGraphNet({Vector3d::Zero(), Vector3d::Zero()}, {{0, 1}}), InputError);  // 0 m
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {0, 5, 1}), InputError);          // perimeter range
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {0, 1}), InputError);             // 2-knot perimeter
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {0, 1, 2, 0}), InputError);       // knot listed twice
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {0, 1, 2}, {0, 0}), InputError);  // corner twice
  EXPECT_THROW(MakeGraphNet(knots, {{0, 1}}, {}, {0}), InputError);  // corner off the perimeter
  try {
    MakeGraphNet(knots, {{0, 1}, {2, 7}});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "thread 1 joins knots 2 and 7: knots are 0 … 2");
  }
}

}  // namespace
}  // namespace ancfnet
