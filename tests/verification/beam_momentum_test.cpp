// The angular momentum of beam sections' spin (analysis/momentum.hpp):
//  - a straight beam spinning about its axis at ω has L = ρ I_p L ω (its centre line is at rest);
//  - a free beam that spins and tumbles keeps its total angular momentum under the implicit
//    midpoint rule (Σ eᵢ × (M ė)ᵢ is a quadratic invariant of it), while the spin and the
//    tumble exchange momentum as the rod precesses (the centre line's part alone changes).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ancfnet/analysis/momentum.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kDiameter = 0.1, kLength = 1.0, kDensity = 1000.0;

// A free steel-stiff rod along x from 0 to L, turning rigidly at ω about its midpoint.
Model SpinningRod(const Vector3d& angular_velocity) {
  ModelBuilder builder;
  builder.AddCable(
      {.name = "rod",
       .start = Vector3d::Zero(),
       .end = Vector3d(kLength, 0.0, 0.0),
       .num_elements = 4,
       .properties = MakeCableProperties({.youngs_modulus = 2e11, .density = kDensity},
                                         MakeCircleSection(kDiameter)),
       .beam = BeamCableSpec{
           .material = {.youngs_modulus = 2e11, .poisson_ratio = 0.3, .density = kDensity},
           .section = MakeCircleBeamSection(kDiameter, 0.3),
           .orientation = Vector3d::UnitY()}});
  builder.SetInitialVelocity("rod", Vector3d::Zero(), angular_velocity,
                             Vector3d(0.5 * kLength, 0.0, 0.0));
  return builder.Build();
}

TEST(BeamMomentum, AxialSpinIsRhoIpLOmega) {
  const double spin = 20.0;  // rad/s
  const Model model = SpinningRod(Vector3d(spin, 0.0, 0.0));
  const Workspace ws(model);
  const State state = MakeInitialState(model);
  const double polar = std::numbers::pi * std::pow(kDiameter, 4) / 32.0;  // I_p = I_y + I_z
  const Vector3d expected(kDensity * polar * kLength * spin, 0.0, 0.0);
  const Vector3d l = CalcAngularMomentum(model, ws, state.q, state.v);
  EXPECT_LT((l - expected).norm(), 1e-12 * expected.norm()) << l.transpose();
  EXPECT_LT(CalcLinearMomentum(model, ws, state.v).norm(), 1e-15);
}

TEST(BeamMomentum, FreeSpinningTumblingBeamKeepsItsAngularMomentum) {
  // Spin 20 rad/s about the axis and tumble 2 rad/s about z: L = (I_a 20, 0, I_t 2) is not along
  // ω, so the rod's axis precesses about L, by half a radian in 0.25 s.
  const Model model = SpinningRod(Vector3d(20.0, 0.0, 2.0));
  const Workspace ws(model);
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 1e-3;
  settings.end_time = 0.25;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  State state = MakeInitialState(model);
  const Vector3d l0 = CalcAngularMomentum(model, ws, state.q, state.v);
  double worst = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        worst = std::max(worst, (CalcAngularMomentum(model, ws, s.q, s.v) - l0).norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  // The spin part alone: the sections' L_rot = Σ (M_rot)ᵢⱼ eᵢ × ėⱼ has turned with the rod.
  const double spin_part = l0.x();
  std::printf("spinning, tumbling beam: |L0| = %.6e kg m²/s, worst change %.3e\n", l0.norm(),
              worst);
  EXPECT_GT(spin_part, 0.1 * l0.norm());
  EXPECT_LT(worst, 1e-9 * l0.norm());
}

}  // namespace
}  // namespace ancfnet
