// A prescribed moving point: an anchor moving at constant velocity v drags a mass m through a
// linear spring k from rest. In the anchor's (inertial) frame the mass starts moving back at −v,
// so its position is x(t) = L₀ + v t − (v/ω) sin ωt, ω = √(k/m); the anchor is exactly at v t.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

class MovingAnchor : public ::testing::TestWithParam<IntegratorType> {};

TEST_P(MovingAnchor, DragsAMassAsTheAnalyticalSolution) {
  const double m = 0.2, k = 50.0, v = 0.7, rest = 0.5;
  ModelBuilder builder;
  builder.AddPointMass("anchor", 0.0, Vector3d::Zero());
  builder.MovePointMass("anchor", Vector3d(v, 0, 0));
  builder.AddPointMass("mass", m, Vector3d(rest, 0, 0));
  builder.AddSpringDamper("spring", {"anchor"}, {"mass"}, MakeLinearLaw(k), rest);
  const Model model = builder.Build();
  const double omega = std::sqrt(k / m);
  const double period = 2.0 * std::numbers::pi / omega;
  DynamicSettings settings;
  settings.integrator = GetParam();
  settings.spectral_radius = 1.0;
  settings.time_step = period / 2000.0;
  settings.end_time = 3.0 * period;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  const Index anchor = model.point_masses()[0].dof, mass = model.point_masses()[1].dof;
  double worst_mass = 0.0, worst_anchor = 0.0;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        const double exact = rest + v * s.t - (v / omega) * std::sin(omega * s.t);
        worst_mass = std::max(worst_mass, std::abs(s.q[mass] - exact));
        worst_anchor = std::max(worst_anchor, std::abs(s.q[anchor] - v * s.t));
        EXPECT_DOUBLE_EQ(s.v[anchor], v);
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  // Second-order schemes with 2000 steps per period: ~(ωh)²/24 relative phase error per radian.
  EXPECT_LT(worst_mass, 2e-5 * (v / omega) * 3.0 * 2.0 * std::numbers::pi);
  EXPECT_LT(worst_anchor, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Integrators, MovingAnchor,
                         ::testing::Values(IntegratorType::kGeneralizedAlpha,
                                           IntegratorType::kImplicitMidpoint,
                                           IntegratorType::kExplicitVerlet),
                         [](const auto& info) {
                           switch (info.param) {
                             case IntegratorType::kGeneralizedAlpha:
                               return "GeneralizedAlpha";
                             case IntegratorType::kImplicitMidpoint:
                               return "Midpoint";
                             case IntegratorType::kExplicitVerlet:
                               return "Verlet";
                           }
                           return "";
                         });

}  // namespace
}  // namespace ancfnet
