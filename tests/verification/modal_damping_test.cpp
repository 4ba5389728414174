// Rayleigh and modal ("generic") damping of a cantilever: the damping ratios the modal analysis
// finds are those prescribed; a free decay started in one mode decays at its prescribed ratio;
// Rayleigh damping fitted to modes 1 and 2 misses modes 3–5 by the amounts of ζ = α/(2ω) + βω/2;
// and a free-flying cable with modal damping keeps its linear momentum.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ancfnet/analysis/momentum.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

const std::vector<double> kRatios = {0.01, 0.02, 0.03, 0.04, 0.05};

// The 16-element cantilever bends alike in y and z: its first ten modes are five pairs. Modal
// damping of ten modes gives pair n the ratio kRatios[n].
Model MakeDampedCantilever() {
  ModelBuilder builder = verification::MakeCantilever(16);
  ModalDamping modal;
  modal.num_modes = 10;
  for (double zeta : kRatios) modal.ratios.insert(modal.ratios.end(), {zeta, zeta});
  builder.SetModalDamping(modal);
  return builder.Build();
}

TEST(ModalDamping, ModalAnalysisFindsThePrescribedRatios) {
  const Model model = MakeDampedCantilever();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 12});
  ASSERT_TRUE(modes.converged) << modes.message;
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(modes.damping_ratio[i], kRatios[i / 2], 1e-9) << "mode " << i + 1;
  // Modes beyond those damped get nothing from the modal matrix (the cable has no other damping).
  EXPECT_NEAR(modes.damping_ratio[10], 0.0, 1e-9);
  EXPECT_NEAR(modes.damping_ratio[11], 0.0, 1e-9);
}

TEST(ModalDamping, RayleighFittedToTwoModesMissesTheOthers) {
  ModelBuilder undamped = verification::MakeCantilever(16);
  const Model reference = undamped.Build();
  const ModalResult modes = CalcModes(reference, reference.initial_positions(), {.num_modes = 10});
  ASSERT_TRUE(modes.converged);
  const RayleighDamping fit =
      FitRayleighDamping(modes.frequency_hz[0], kRatios[0], modes.frequency_hz[2], kRatios[1]);
  ModelBuilder builder = verification::MakeCantilever(16);
  builder.SetRayleighDamping(fit);
  const Model model = builder.Build();
  const ModalResult damped = CalcModes(model, model.initial_positions(), {.num_modes = 10});
  ASSERT_TRUE(damped.converged);
  for (int n = 0; n < 5; ++n) {
    const double omega = damped.omega[2 * n];
    const double rayleigh = fit.alpha / (2.0 * omega) + fit.beta * omega / 2.0;
    EXPECT_NEAR(damped.damping_ratio[2 * n], rayleigh, 1e-9) << "mode pair " << n + 1;
    std::printf("mode %d: f = %.3f Hz, Rayleigh ζ = %.4f %% against %.0f %%\n", n + 1,
                damped.frequency_hz[2 * n], 100 * damped.damping_ratio[2 * n], 100 * kRatios[n]);
  }
  EXPECT_NEAR(damped.damping_ratio[0], kRatios[0], 1e-9);  // the fitted modes
  EXPECT_NEAR(damped.damping_ratio[2], kRatios[1], 1e-9);
  EXPECT_GT(damped.damping_ratio[8], 3.0 * kRatios[4]);  // β ω/2 runs away at mode 5
}

// Started at rest in one mode shape with a small amplitude, the tip oscillates at that mode's
// frequency and its successive peaks fall by the logarithmic decrement δ = 2πζ/√(1 − ζ²).
double DecayRatio(int pair) {
  const Model model = MakeDampedCantilever();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 10});
  State state = MakeInitialState(model);
  const VectorXd shape = modes.shapes.col(2 * pair);
  const Index tip = model.NodePositionDof(model.num_nodes() - 1);
  const Index axis = std::abs(shape[tip + 1]) > std::abs(shape[tip + 2]) ? 1 : 2;
  state.q += (1e-4 / std::abs(shape[tip + axis])) * shape;  // 0.1 mm at the tip
  const double period = 1.0 / modes.frequency_hz[2 * pair];
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;  // no numerical damping
  settings.time_step = period / 200.0;
  settings.end_time = 8.0 * period;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-14;
  std::vector<double> time, deflection;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        time.push_back(s.t);
        deflection.push_back(s.q[tip + axis]);
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  // Peaks by parabolic interpolation through the three samples around each local maximum.
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < deflection.size(); ++i) {
    const double a = deflection[i - 1], b = deflection[i], c = deflection[i + 1];
    if (b > a && b >= c && b > 0.0)
      peaks.push_back(b - 0.125 * (c - a) * (c - a) / (a - 2 * b + c));
  }
  EXPECT_GE(peaks.size(), 6u);
  const double delta = std::log(peaks.front() / peaks.back()) / (peaks.size() - 1);
  return delta / std::sqrt(4 * std::numbers::pi * std::numbers::pi + delta * delta);
}

TEST(ModalDamping, FreeDecayInEachModeAtItsPrescribedRatio) {
  for (int pair = 0; pair < 3; ++pair) {
    const double zeta = DecayRatio(pair);
    std::printf("mode pair %d: decay ζ = %.5f (prescribed %.2f)\n", pair + 1, zeta, kRatios[pair]);
    EXPECT_NEAR(zeta, kRatios[pair], 0.05 * kRatios[pair]) << "pair " << pair + 1;
  }
}

// A free–free cable with modal damping of its first 6 elastic modes, flying and spinning slowly
// while it vibrates in its first mode: the damping force M Φ D Φᵀ M v is orthogonal to rigid
// translations (Φᵀ M 1 = 0), so the linear momentum stays.
TEST(ModalDamping, FreeFlyingCableKeepsItsMomentum) {
  Material steel{.youngs_modulus = 2.0e11, .density = 7800.0};
  ModelBuilder builder;
  builder.AddCable({.name = "cable",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 8,
                    .properties = MakeCableProperties(steel, MakeRectangleSection(0.01, 0.01))});
  ModalDamping modal;
  modal.num_modes = 6;
  modal.ratios.assign(6, 0.05);
  builder.SetModalDamping(modal);
  builder.SetInitialVelocity("cable", Vector3d(0.3, -0.2, 0.5), Vector3d(0.0, 0.0, 0.2),
                             Vector3d(0.5, 0.0, 0.0));
  const Model model = builder.Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 6});
  ASSERT_TRUE(modes.converged);
  State state = MakeInitialState(model);
  state.v += 0.05 * modes.shapes.col(5);  // the first elastic mode (after 5 rigid ones)
  ASSERT_TRUE(modes.rigid[4]);
  ASSERT_FALSE(modes.rigid[5]);
  const Workspace ws(model);
  const Vector3d p0 = CalcLinearMomentum(model, ws, state.v);
  DynamicSettings settings;
  settings.time_step = 1e-4;
  settings.end_time = 0.2;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  double worst = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        worst = std::max(worst, (CalcLinearMomentum(model, ws, s.v) - p0).norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_LT(worst, 1e-9 * p0.norm());
}

}  // namespace
}  // namespace ancfnet
