// A block on an incline, one degree of freedom x down the slope: m ẍ = m g sin θ + F_t(ẋ),
// normal force N = m g cos θ, integrated by implicit Euler with Newton on the end-of-step
// velocity (the friction law's ∂F_t/∂v in the iteration, as an implicit integrator would use
// it), the slope load ramped up over 1 s. Expected: sliding at a = g (sin θ − μ_k cos θ) above
// tan θ = μ_s; below it the bristle law sticks and the regularised laws creep at the speed where
// their μ(v) equals tan θ (docs/validation.md, "Contact force laws").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "ancfnet/contact/laws/friction_law.hpp"

namespace ancfnet {
namespace {

constexpr double kG = 9.81;
constexpr double kMass = 2.0;
constexpr double kStep = 1e-4;
// The slope load m g sin θ grows linearly from 0 over this time (the plane is tilted slowly): a
// load released suddenly overshoots the bristle deflection by up to twice its static value, and
// a fast ramp makes the block pre-slide fast enough to fall down the Stribeck curve; either
// breaks it loose near tan θ = μ_s, as with a real block.
constexpr double kLoadRamp = 1.0;

struct Motion {
  double t = 0.0;  // time (s)
  double x = 0.0;  // distance down the slope (m)
  double v = 0.0;  // speed down the slope (m/s)
  double z = 0.0;  // bristle deflection (m), LuGre only
};

// One implicit-Euler step; returns the new motion. Newton on r(v) = m (v − v_n)/h − m g sinθ −
// F_t(v), which is increasing for the step used here (m/h ≫ |∂F_t/∂v| where it is positive).
Motion Step(const FrictionLaw& law, double theta, const Motion& now) {
  const double normal = kMass * kG * std::cos(theta);
  const auto friction = [&](double v, double* z) {
    if (law.kind == FrictionLawKind::kLuGre) {
      const BristleStep s = law.StepBristle(now.z, v, normal, kStep);
      *z = s.deflection;
      return s.friction;
    }
    *z = 0.0;
    return law.Evaluate(v, normal);
  };
  const double load = kMass * kG * std::sin(theta) * std::min((now.t + kStep) / kLoadRamp, 1.0);
  double v = now.v;
  double z = now.z;
  for (int it = 0; it < 60; ++it) {
    const FrictionForce f = friction(v, &z);
    const double r = kMass * (v - now.v) / kStep - load - f.force;
    const double dr = kMass / kStep - f.dforce_dvelocity;
    const double dv = -r / dr;
    v += dv;
    if (std::abs(dv) < 1e-14 * (1.0 + std::abs(v))) break;
  }
  friction(v, &z);
  return {now.t + kStep, now.x + kStep * v, v, z};
}

Motion Simulate(const FrictionLaw& law, double theta, double duration, Motion m = {}) {
  const int steps = static_cast<int>(std::lround(duration / kStep));
  for (int i = 0; i < steps; ++i) m = Step(law, theta, m);
  return m;
}

// The speed where μ(v) = tan θ for a regularised law: bisection on [0, hi], where μ(v) rises
// through tan θ (below the Stribeck fall of the tanh law).
double CreepSpeed(const FrictionLaw& law, double theta) {
  double lo = 0.0;
  double hi =
      law.kind == FrictionLawKind::kAmbrosio ? law.ramp_end_speed : 3.0 * law.regularization_speed;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double mu = -law.Evaluate(mid, 1.0).force;
    (mu < std::tan(theta) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Sliding acceleration measured over 1.5 … 2 s, when v ≫ every regularisation speed.
double SlidingAcceleration(const FrictionLaw& law, double theta) {
  const Motion a = Simulate(law, theta, 1.5);
  const Motion b = Simulate(law, theta, 0.5, a);
  return (b.v - a.v) / 0.5;
}

const double kMuS = 0.5;
const double kMuK = 0.3;

TEST(Incline, BristleLawSticksBelowStaticCoefficientAndSlidesAbove) {
  // σ1 = 2 √(σ0/(g cosθ)) makes the bristle mode about critically damped.
  const double sigma0 = 1e4;
  const FrictionLaw law = MakeLuGreFriction(kMuS, kMuK, 1e-2, sigma0, 60.0, 0.0);
  for (double tan_theta : {0.2, 0.4, 0.48}) {  // μ_k < 0.4 < 0.48 < μ_s: sticks even so
    const double theta = std::atan(tan_theta);
    const Motion one = Simulate(law, theta, 2.0);
    const Motion two = Simulate(law, theta, 1.0, one);
    // Pre-sliding only: loaded slowly, ż = ẋ (1 − σ0 z/g) gives
    // x = −(μ_s/σ0) ln(1 − tan θ/μ_s) at z = tan θ/σ0 (a few 1e-5 m) ...
    const double presliding = -(kMuS / sigma0) * std::log(1 - tan_theta / kMuS);
    EXPECT_NEAR(two.x, presliding, 0.15 * presliding) << "tan theta " << tan_theta;
    // ... and no drift once the load is constant.
    EXPECT_LT(std::abs(two.x - one.x), 1e-9) << "tan theta " << tan_theta;
    EXPECT_LT(std::abs(two.v), 1e-9) << "tan theta " << tan_theta;
    std::printf("LuGre tan(theta) = %.2f: x(3 s) = %.4e m (pre-sliding %.4e m), drift %.1e m\n",
                tan_theta, two.x, presliding, two.x - one.x);
  }
  for (double tan_theta : {0.55, 0.8}) {
    const double theta = std::atan(tan_theta);
    const double expected = kG * (std::sin(theta) - kMuK * std::cos(theta));
    const double a = SlidingAcceleration(law, theta);
    EXPECT_NEAR(a, expected, 0.01 * expected) << "tan theta " << tan_theta;
    std::printf("LuGre tan(theta) = %.2f: a = %.5f m/s^2, expected %.5f\n", tan_theta, a, expected);
  }
}

TEST(Incline, RegularisedLawsSlideAndCreep) {
  const FrictionLaw ambrosio = MakeAmbrosioFriction(kMuK, 1e-4, 1e-3);
  const FrictionLaw tanh_law = MakeTanhFriction(kMuS, kMuK, 1e-3, 1e-2);
  for (const FrictionLaw* law : {&ambrosio, &tanh_law}) {
    const char* name = law == &ambrosio ? "Ambrosio" : "tanh";
    for (double tan_theta : {0.55, 0.8}) {
      const double theta = std::atan(tan_theta);
      const double expected = kG * (std::sin(theta) - kMuK * std::cos(theta));
      EXPECT_NEAR(SlidingAcceleration(*law, theta), expected, 0.01 * expected) << name;
    }
    // Below the sticking limit (tan θ = 0.2 < μ_k; and 0.4 for tanh, between μ_k and μ_s) the
    // block does not stop: it creeps at the speed where μ(v) = tan θ.
    for (double tan_theta : {0.2, 0.4}) {
      if (law == &ambrosio && tan_theta > kMuK) continue;  // Ambrósio's law has one μ
      const double theta = std::atan(tan_theta);
      const double creep = CreepSpeed(*law, theta);
      const Motion m = Simulate(*law, theta, 2.0);
      EXPECT_NEAR(m.v, creep, 0.01 * creep) << name << " tan theta " << tan_theta;
      std::printf("%s tan(theta) = %.2f: creeps at %.4e m/s (predicted %.4e m/s)\n", name,
                  tan_theta, m.v, creep);
    }
  }
  // Ambrósio's creep speed in closed form: c_d = tan θ/μ, v = v0 + (v1 − v0) tan θ/μ.
  EXPECT_NEAR(CreepSpeed(ambrosio, std::atan(0.2)), 1e-4 + 9e-4 * 0.2 / kMuK, 1e-12);
}

}  // namespace
}  // namespace ancfnet
