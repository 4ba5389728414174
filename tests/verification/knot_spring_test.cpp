// A knot spring between two masses: the relative motion of two point masses joined by a linear
// spring-damper oscillates at ω = √(k (m₁ + m₂)/(m₁ m₂)), the total momentum is conserved, and a
// tension-only link transmits no compression.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ancfnet/elements/connection_law.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

struct Trajectory {
  std::vector<double> time;
  std::vector<double> separation;  // |r₂ − r₁| (m)
  std::vector<Vector3d> momentum;  // m₁ v₁ + m₂ v₂ (kg m/s)
};

// Two masses on the x-axis, L₀ = 0.5 m apart at rest length, the second one pulled 10 mm out and
// both given a common drift; generalised-α with ρ∞ = 1 (no numerical damping), h = T/400.
Trajectory Simulate(const ConnectionLaw& law, double m1, double m2, double stretch,
                    double duration, double h) {
  ModelBuilder builder;
  const Vector3d drift(0.3, -0.2, 0.1);
  builder.AddPointMass("m1", m1, Vector3d::Zero(), drift);
  builder.AddPointMass("m2", m2, Vector3d(0.5 + stretch, 0.0, 0.0), drift);
  builder.AddSpringDamper("link", {"m1"}, {"m2"}, law, 0.5);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.spectral_radius = 1.0;
  settings.time_step = h;
  settings.end_time = duration;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  Trajectory trajectory;
  State state = MakeInitialState(model);
  const Index d1 = model.point_masses()[0].dof, d2 = model.point_masses()[1].dof;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        trajectory.time.push_back(s.t);
        trajectory.separation.push_back((s.q.segment<3>(d2) - s.q.segment<3>(d1)).norm());
        trajectory.momentum.push_back(m1 * s.v.segment<3>(d1) + m2 * s.v.segment<3>(d2));
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  return trajectory;
}

// Mean period from the upward crossings of the mean separation (linear interpolation).
double MeasurePeriod(const Trajectory& t, double mean) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < t.time.size(); ++i) {
    const double a = t.separation[i - 1] - mean, b = t.separation[i] - mean;
    if (a < 0.0 && b >= 0.0) crossings.push_back(t.time[i - 1] + (t.time[i] - t.time[i - 1]) * a / (a - b));
  }
  EXPECT_GE(crossings.size(), 3u);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(KnotSpring, OscillatesAtTheAnalyticalFrequency) {
  const double k = 200.0, m1 = 0.05, m2 = 0.15;
  const double omega = std::sqrt(k * (m1 + m2) / (m1 * m2));
  const double period = 2.0 * std::numbers::pi / omega;
  const Trajectory t = Simulate(MakeLinearLaw(k), m1, m2, 0.01, 5.0 * period, period / 400.0);
  // Trapezoidal rule period error (ωh)²/12 ≈ 2e-5: well inside the 0.1 %.
  EXPECT_NEAR(MeasurePeriod(t, 0.5), period, 1e-3 * period);
  const Vector3d p0 = t.momentum.front();
  for (const Vector3d& p : t.momentum) EXPECT_LT((p - p0).norm(), 1e-9 * p0.norm());
}

TEST(KnotSpring, TensionOnlyLinkTransmitsNoCompression) {
  // Pushed together by 10 mm with a tension-only link: no force, the masses keep their velocity
  // (both drift alike), so the separation stays 0.49 m.
  const Trajectory t = Simulate(MakeTensionOnlyLaw(200.0, 0.0), 0.05, 0.15, -0.01, 0.2, 1e-3);
  for (double d : t.separation) EXPECT_NEAR(d, 0.49, 1e-12);
}

}  // namespace
}  // namespace ancfnet
