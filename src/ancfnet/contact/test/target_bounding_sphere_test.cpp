// The bounding ball of each kind of target (CalcTargetBoundingSphere), which culls far contact
// pairs: every point of the target lies inside it, so the distance of any point x to the target
// is at least |x − c| − R; and it is not loose (a point of the target lies near its surface).

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/target_distance.hpp"

namespace ancfnet {
namespace {

std::vector<ContactTarget> Targets() {
  std::vector<ContactTarget> targets(5);
  targets[0].kind = ContactTarget::Kind::kSphere;
  targets[0].point = Vector3d(0.1, -0.2, 0.3);
  targets[0].radius = 0.4;
  targets[1].kind = ContactTarget::Kind::kBox;
  targets[1].point = Vector3d(-0.5, 0.0, 0.2);
  targets[1].half_extents = Vector3d(0.3, 0.2, 0.1);
  targets[1].rotation = Eigen::AngleAxisd(0.6, Vector3d(1.0, 1.0, 0.0).normalized()).matrix();
  targets[2].kind = ContactTarget::Kind::kCylinder;
  targets[2].point = Vector3d(0.0, 0.4, 0.0);
  targets[2].normal = Vector3d(0.0, 1.0, 1.0).normalized();
  targets[2].radius = 0.2;
  targets[2].half_length = 0.5;
  targets[3].kind = ContactTarget::Kind::kCapsule;
  targets[3].point = Vector3d(0.3, 0.3, -0.3);
  targets[3].normal = Vector3d(1.0, 0.0, 0.0);
  targets[3].radius = 0.1;
  targets[3].half_length = 0.6;
  targets[4].kind = ContactTarget::Kind::kMesh;
  TriangleMesh ball = MakeIcosphere(0.25, 2);
  ball.vertices.colwise() += Vector3d(1.0, 2.0, -1.0);
  targets[4].mesh = std::make_shared<const MeshBvh>(std::move(ball));
  return targets;
}

TEST(TargetBoundingSphere, HoldsTheTargetAndBoundsEveryDistanceFromBelow) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  for (const ContactTarget& target : Targets()) {
    const TargetBoundingSphere ball = CalcTargetBoundingSphere(target);
    double tightest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 20000; ++i) {
      const Vector3d x(coordinate(random), coordinate(random), coordinate(random));
      const double distance = CalcPointTargetDistance(target, x).distance;
      const double bound = (x - ball.center).norm() - ball.radius;
      EXPECT_GE(distance, bound - 1e-12) << "kind " << static_cast<int>(target.kind);
      tightest = std::min(tightest, distance - bound);
    }
    // Not loose: somewhere the bound comes within 5 cm of the distance.
    EXPECT_LT(tightest, 0.05) << "kind " << static_cast<int>(target.kind);
  }
}

TEST(TargetBoundingSphere, APlaneHasNoBall) {
  ContactTarget plane;
  EXPECT_TRUE(std::isinf(CalcTargetBoundingSphere(plane).radius));
}

}  // namespace
}  // namespace ancfnet
