#include "ancfnet/contact/elastic_step_force.hpp"

#include <gtest/gtest.h>

namespace ancfnet {
namespace {

const NormalLaw kHertz = MakeHertzContactLaw(1.0e6, 1.5);

// A point moving from x₀ to x₁ against a sphere of radius R at the origin, probe radius r.
struct Sphere {
  double radius = 0.3;
  double probe = 0.001;
  double Penetration(const Vector3d& x) const { return probe - (x.norm() - radius); }
};

// f̄·d = −(Φ(δ₁) − Φ(δ₀)) on a curved surface, for entering, pressing and leaving steps.
TEST(ElasticStepForce, WorkEqualsEnergyChange) {
  const Sphere s;
  const Vector3d x0(0.01, 0.02, 0.2998);  // δ₀ = 0.54 mm
  for (const Vector3d& x1 : {Vector3d(0.03, -0.01, 0.2990), Vector3d(0.012, 0.021, 0.2992),
                             Vector3d(0.05, 0.04, 0.3030)}) {  // δ₁ = 0.34, 0.83 mm, apart
    const double d0 = s.Penetration(x0);
    const double d1 = s.Penetration(x1);
    const Vector3d n = (0.5 * (x0 + x1)).normalized();
    const Vector3d f = CalcElasticStepForce(kHertz, d0, d1, n, x1 - x0, 1e-9);
    const double change = kHertz.CalcElasticEnergy(d1) - kHertz.CalcElasticEnergy(d0);
    EXPECT_NEAR(f.dot(x1 - x0), -change, 1e-12 * std::max(std::abs(change), 1e-9));
    // The force stays close to the normal, pushing out.
    EXPECT_GT(f.dot(n), 0.9 * f.norm());
  }
}

// As the step shrinks, f̄ tends to the law's force at the midpoint along its normal (first
// order in the step here: the error shrinks at least tenfold per tenfold step).
TEST(ElasticStepForce, TendsToTheLawsForceForASmallStep) {
  const Sphere s;
  const Vector3d x0(0.01, 0.02, 0.2998);
  const Vector3d move(0.02, -0.01, -0.0004);
  double previous = 0.0;
  for (double scale : {1e-2, 1e-3, 1e-4}) {
    const Vector3d x1 = x0 + scale * move;
    const Vector3d mid = 0.5 * (x0 + x1);
    const Vector3d n = mid.normalized();
    const Vector3d f =
        CalcElasticStepForce(kHertz, s.Penetration(x0), s.Penetration(x1), n, x1 - x0, 1e-12);
    const Vector3d law = kHertz.Evaluate(s.Penetration(mid), 0.0, 1.0).elastic_force * n;
    const double error = (f - law).norm() / law.norm();
    if (previous > 0.0) {
      EXPECT_LT(error, 0.1 * previous);
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

// A probe sticking on a plane: a displacement of 10⁻¹⁵ m and penetrations that differ by their
// round-off must not turn that round-off into a tangential force.
TEST(ElasticStepForce, ASteadyProbeGetsTheNormalForceOnly) {
  const Vector3d n = Vector3d::UnitZ();
  const double delta = 4.5e-5;
  const Vector3d f = CalcElasticStepForce(kHertz, delta, delta + 3e-18, n,
                                          Vector3d(1e-15, 0.0, 0.0), 1e-6 * 0.01);
  EXPECT_EQ(f.x(), 0.0);
  EXPECT_NEAR(f.z(), kHertz.Evaluate(delta, 0.0, 1.0).elastic_force, 1e-9 * f.norm());
}

TEST(ElasticStepForce, ZeroWhenApartAtBothEnds) {
  EXPECT_EQ(CalcElasticStepForce(kHertz, -1e-4, -2e-5, Vector3d::UnitZ(), Vector3d(0, 0, 1e-4), 0.0),
            Vector3d::Zero());
}

}  // namespace
}  // namespace ancfnet
