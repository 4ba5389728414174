// The identification round trip of issue 5: a cantilever with modal damping ζ = 1, 2, 3, 4, 5 %
// on modes 1–5, struck at the tip, simulated with the full nonlinear model; the matrix pencil
// finds the five frequencies and damping ratios back. With Rayleigh damping fitted to modes 1 and
// 2 the same procedure shows how far Rayleigh's ζ is from the measured one at modes 3–5.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ancfnet/analysis/modal_identification.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

const std::vector<double> kRatios = {0.01, 0.02, 0.03, 0.04, 0.05};

// The 16-element steel cantilever, bending in the xz-plane only (its y coordinates fixed), so
// that its lowest modes are single: five bending modes below the first axial one (1250 Hz).
ModelBuilder MakePlanarCantilever() {
  ModelBuilder builder = verification::MakeCantilever(16);
  for (int i = 1; i <= 16; ++i)
    builder.FixCoordinates({"beam", i / 16.0}, {false, true, false, false, true, false});
  return builder;
}

struct Record {
  std::vector<double> time;
  MatrixXd signals;  // tip and mid-span vertical velocity, one column each
  VectorXd frequency_hz;
};

// A blow at the tip along z by a soft hammer: the impulse J = 10⁻⁴ N s reaches the five lowest
// modes only, v₀ = Σᵢ φᵢ (φᵢ · e_z) J (the modal expansion of M⁻¹ e_z J, cut after five modes),
// so that the unresolved stiff modes the step cannot carry are not excited. 0.4 s with the
// implicit midpoint rule (no numerical damping), 40 steps per period of mode 5.
Record StrikeAndRecord(const Model& model) {
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 10});
  EXPECT_TRUE(modes.converged) << modes.message;
  State state = MakeInitialState(model);
  const Index tip = model.NodePositionDof(model.num_nodes() - 1);
  for (int i = 0; i < 5; ++i) state.v += 1e-4 * modes.shapes(tip + 2, i) * modes.shapes.col(i);
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 1.0 / (40.0 * modes.frequency_hz[4]);
  settings.end_time = settings.time_step * std::round(0.4 / settings.time_step);  // uniform samples
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-14;
  const Index mid = model.NodePositionDof(model.num_nodes() / 2);
  Record record;
  std::vector<double> tip_v, mid_v;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        record.time.push_back(s.t);
        tip_v.push_back(s.v[tip + 2]);
        mid_v.push_back(s.v[mid + 2]);
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  record.signals.resize(static_cast<Index>(tip_v.size()), 2);
  for (std::size_t i = 0; i < tip_v.size(); ++i) {
    record.signals(static_cast<Index>(i), 0) = tip_v[i];
    record.signals(static_cast<Index>(i), 1) = mid_v[i];
  }
  record.frequency_hz = modes.frequency_hz;
  return record;
}

std::vector<IdentifiedMode> Identify(const Record& record) {
  ModalIdentificationOptions options;
  options.modes = 5;
  options.extra_poles = 10;
  options.decimation = 1;  // every sample: mode 5 with Rayleigh's 17 % lives for a few periods
  options.signal_names = {"tip.vz", "mid.vz"};
  const VectorXd time =
      Eigen::Map<const VectorXd>(record.time.data(), static_cast<Index>(record.time.size()));
  return IdentifyModes(time, record.signals, options).modes;
}

TEST(IdentificationRoundTrip, ModalDampingIsIdentifiedBackWithinFivePercent) {
  // Damping "measured" at the five modes, given as a table ζ(f) (the modes above the fifth, not
  // excited here, would get its last value, 5 %).
  const Model undamped = MakePlanarCantilever().Build();
  const ModalResult reference = CalcModes(undamped, undamped.initial_positions(), {.num_modes = 5});
  ASSERT_TRUE(reference.converged);
  ModalDamping modal;
  modal.num_modes = 10;
  for (int i = 0; i < 5; ++i) modal.table.emplace_back(reference.frequency_hz[i], kRatios[i]);
  ModelBuilder builder = MakePlanarCantilever();
  builder.SetModalDamping(modal);
  const Model model = builder.Build();
  const Record record = StrikeAndRecord(model);
  const std::vector<IdentifiedMode> modes = Identify(record);
  ASSERT_EQ(modes.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    std::printf("mode %d: f = %.4f Hz (modal analysis %.4f), ζ = %.4f %% (prescribed %.0f %%)\n",
                i + 1, modes[i].frequency, record.frequency_hz[i], 100 * modes[i].damping_ratio,
                100 * kRatios[i]);
    EXPECT_NEAR(modes[i].frequency / record.frequency_hz[i], 1.0, 5e-3) << "mode " << i + 1;
    EXPECT_NEAR(modes[i].damping_ratio, kRatios[i], 0.05 * kRatios[i]) << "mode " << i + 1;
  }
}

TEST(IdentificationRoundTrip, RayleighFittedToModesOneAndTwoIsOffAbove) {
  const Model undamped = MakePlanarCantilever().Build();
  const ModalResult reference = CalcModes(undamped, undamped.initial_positions(), {.num_modes = 5});
  ASSERT_TRUE(reference.converged);
  const RayleighDamping fit = FitRayleighDamping(reference.frequency_hz[0], kRatios[0],
                                                 reference.frequency_hz[1], kRatios[1]);
  ModelBuilder builder = MakePlanarCantilever();
  builder.SetRayleighDamping(fit);
  const Model model = builder.Build();
  const std::vector<IdentifiedMode> modes = Identify(StrikeAndRecord(model));
  ASSERT_EQ(modes.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const double omega = 2.0 * M_PI * reference.frequency_hz[i];
    const double rayleigh = fit.alpha / (2.0 * omega) + fit.beta * omega / 2.0;
    std::printf("mode %d: identified ζ = %.3f %%, Rayleigh curve %.3f %%, measured %.0f %%\n",
                i + 1, 100 * modes[i].damping_ratio, 100 * rayleigh, 100 * kRatios[i]);
    EXPECT_NEAR(modes[i].damping_ratio, rayleigh, 0.05 * rayleigh) << "mode " << i + 1;
  }
  EXPECT_GT(modes[4].damping_ratio, 2.0 * kRatios[4]);  // Rayleigh overdamps mode 5
}

}  // namespace
}  // namespace ancfnet
