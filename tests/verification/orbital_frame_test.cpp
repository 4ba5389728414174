// Clohessy–Wiltshire relative motion in the Hill frame of a target on a circular orbit: a free
// point mass follows the analytical solution over one orbit, and a free cable keeps the Jacobi
// integral (kinetic + strain + tidal potential) constant.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kMeanMotion = 0.0011;  // rad/s, a low Earth orbit (period about 95 min)

// Clohessy & Wiltshire (1960): x radial, y along-track, z orbit normal.
Vector3d AnalyticalPosition(const Vector3d& r0, const Vector3d& v0, double t) {
  const double n = kMeanMotion, c = std::cos(n * t), s = std::sin(n * t);
  return {(4.0 - 3.0 * c) * r0.x() + s / n * v0.x() + 2.0 / n * (1.0 - c) * v0.y(),
          6.0 * (s - n * t) * r0.x() + r0.y() - 2.0 / n * (1.0 - c) * v0.x() +
              (4.0 * s - 3.0 * n * t) / n * v0.y(),
          c * r0.z() + s / n * v0.z()};
}

DynamicSettings OneOrbit(double steps_per_orbit) {
  DynamicSettings settings;
  const double period = 2.0 * std::numbers::pi / kMeanMotion;
  settings.spectral_radius = 1.0;
  settings.time_step = period / steps_per_orbit;
  settings.end_time = period;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-12;
  return settings;
}

TEST(OrbitalFrame, FreePointMassFollowsClohessyWiltshireOverOneOrbit) {
  const Vector3d r0(10.0, -5.0, 3.0), v0(0.01, -0.02, 0.005);
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddPointMass("chaser", 2.0, r0, v0);
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  double worst = 0.0, scale = 0.0;
  const SolveResult result = SolveDynamic(
      model, OneOrbit(20000), 0.0,
      [&](const State& s, const EnergyAccount&) {
        const Vector3d exact = AnalyticalPosition(r0, v0, s.t);
        worst = std::max(worst, (s.q.segment<3>(0) - exact).norm());
        scale = std::max(scale, exact.norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_LT(worst, 1e-6 * scale);  // trapezoidal rule: phase error about (n h)² n t / 12
}

TEST(OrbitalFrame, FreeCableKeepsTheJacobiIntegral) {
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddCable({.name = "tether",
                    .start = Vector3d(5.0, 0.0, 0.0),
                    .end = Vector3d(25.0, 0.0, 0.0),
                    .num_elements = 4,
                    .properties = MakeCableProperties({.youngs_modulus = 1e9, .density = 1400},
                                                      MakeCircleSection(0.002))});
  builder.SetInitialVelocity("tether", Vector3d(0.0, 0.01, 0.0), Vector3d(0, 0, 0.002),
                             Vector3d(15.0, 0.0, 0.0));
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  double first = 0.0, worst = 0.0, kinetic = 0.0;
  bool started = false;
  DynamicSettings settings = OneOrbit(2000);
  settings.end_time /= 4.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State&, const EnergyAccount& e) {
        const double jacobi = e.kinetic + e.strain + e.gravity;
        if (!started) first = jacobi;
        started = true;
        worst = std::max(worst, std::abs(jacobi - first));
        kinetic = std::max(kinetic, e.kinetic);
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_LT(worst, 1e-6 * kinetic);
}

}  // namespace
}  // namespace ancfnet
