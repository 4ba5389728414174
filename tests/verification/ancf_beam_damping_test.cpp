// Kelvin–Voigt damping of the ANCF beam (elements/ancf_beam.hpp, issue 13) against its closed
// form. A material σ = E ε + η ε̇ = E (ε + τ ε̇) gives a mode whose energy lies in strains of one
// retardation time τ the damping ratio ζ = η ω / (2E) = τ ω / 2 (its damping matrix is τ times its
// stiffness; e.g. Clough & Penzien 2003, §12-5):
//  - modal analysis of an aluminium cantilever (L = 1 m, 10 × 10 mm): with τ_ε = τ_κ every mode
//    (bending in both planes, torsion, axial) has ζ = τ ω / 2; with τ_κ = 0 only the axial mode is
//    damped, with ζ = τ_ε ω / 2 (the bending modes keep the shear's small share);
//  - a free decay of the first bending mode in the time domain (implicit midpoint, no numerical
//    damping): the matrix pencil finds ζ₁ = τ_κ ω₁ / 2 at the model's ω₁ (within 0.5 % of
//    Euler–Bernoulli's 1.8751² √(EI/(ρA L⁴)) with 8 elements), and the energy account (kinetic +
//    strain + dissipated) keeps the launch energy.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ancfnet/analysis/modal_identification.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/modal.hpp"

namespace ancfnet {
namespace {

constexpr double kLength = 1.0;
constexpr double kSide = 0.01;
constexpr double kYoungs = 71.7e9;
constexpr double kDensity = 2700.0;

// The clamped aluminium bar with the damping times (τ_ε, τ_κ), `elements` beam elements.
ModelBuilder MakeDampedCantilever(double axial_time, double bending_time, int elements) {
  const BeamMaterial aluminium{.youngs_modulus = kYoungs,
                               .poisson_ratio = 0.33,
                               .density = kDensity,
                               .axial_damping_time = axial_time,
                               .bending_damping_time = bending_time};
  CableProperties drawn;
  drawn.axial_damping_time = axial_time;
  drawn.bending_damping_time = bending_time;
  ModelBuilder builder;
  builder.AddCable({.name = "bar",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(kLength, 0.0, 0.0),
                    .num_elements = elements,
                    .properties = drawn,
                    .beam = BeamCableSpec{.material = aluminium,
                                          .section = MakeRectangleBeamSection(kSide, kSide, 0.33),
                                          .orientation = Vector3d::UnitY()}});
  builder.AddClamp({"bar", 0.0});
  return builder;
}

// Index of the mode nearest to `frequency` (Hz).
Eigen::Index NearestMode(const ModalResult& modes, double frequency) {
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < modes.frequency_hz.size(); ++i)
    if (std::abs(modes.frequency_hz[i] - frequency) <
        std::abs(modes.frequency_hz[best] - frequency))
      best = i;
  return best;
}

// The first axial mode of a fixed–free rod, f = √(E/ρ) / (4L) = 1288 Hz; the first torsion mode
// (727 Hz) and seven bending pairs lie below it, so 16 modes hold all three kinds.
constexpr int kModes = 16;
double AxialFrequency() { return std::sqrt(kYoungs / kDensity) / (4.0 * kLength); }

TEST(AncfBeamDamping, EqualRetardationTimesDampEveryModeByTauOmegaOverTwo) {
  const double tau = 1e-5;
  const Model model = MakeDampedCantilever(tau, tau, 16).Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = kModes});
  ASSERT_TRUE(modes.converged) << modes.message;
  const Eigen::Index axial = NearestMode(modes, AxialFrequency());
  EXPECT_NEAR(modes.frequency_hz[axial], AxialFrequency(), 5e-3 * AxialFrequency());
  double worst = 0.0;
  for (Eigen::Index i = 0; i < kModes; ++i) {
    const double expected = 0.5 * tau * modes.omega[i];
    worst = std::max(worst, std::abs(modes.damping_ratio[i] / expected - 1.0));
    EXPECT_NEAR(modes.damping_ratio[i], expected, 1e-3 * expected)
        << "mode " << i + 1 << " at " << modes.frequency_hz[i] << " Hz";
  }
  std::printf(
      "tau_eps = tau_kappa: %d modes up to %.1f Hz, largest |zeta / (tau omega / 2) - 1| "
      "%.2e\n",
      kModes, modes.frequency_hz[kModes - 1], worst);
}

TEST(AncfBeamDamping, AxialRetardationTimeDampsTheAxialMode) {
  const double tau = 1e-5;
  const Model model = MakeDampedCantilever(tau, 0.0, 16).Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = kModes});
  ASSERT_TRUE(modes.converged) << modes.message;
  const Eigen::Index axial = NearestMode(modes, AxialFrequency());
  const double expected = 0.5 * tau * modes.omega[axial];
  std::printf("axial mode %.1f Hz: zeta %.6e (tau omega / 2 = %.6e)\n", modes.frequency_hz[axial],
              modes.damping_ratio[axial], expected);
  EXPECT_NEAR(modes.damping_ratio[axial], expected, 1e-3 * expected);
  // Bending and torsion store nothing in Γ₁; a bending mode keeps the share of its energy in
  // the shear strains Γ₂, Γ₃ (damped by τ_ε too), Timoshenko's (k r)² E/(k_s G) ≈ 1.4 % for the
  // eighth pair (k = 15π/2L, r = a/√12), less below it.
  for (Eigen::Index i = 0; i < kModes; ++i) {
    if (i == axial) continue;
    EXPECT_LT(modes.damping_ratio[i], 0.02 * 0.5 * tau * modes.omega[i])
        << "mode " << i + 1 << " at " << modes.frequency_hz[i] << " Hz";
  }
}

TEST(AncfBeamDamping, FreeDecayOfTheFirstBendingMode) {
  // τ_κ = 2 ms: ζ₁ = τ ω₁ / 2 ≈ 0.052; the higher modes, excited a little by the start (a rigid
  // rotation about the clamp, tip speed 0.1 m/s), decay at least six times faster.
  const double tau = 2e-3;
  ModelBuilder builder = MakeDampedCantilever(0.0, tau, 8);
  builder.SetInitialVelocity("bar", Vector3d::Zero(), Vector3d(0.0, 0.0, 0.1), Vector3d::Zero());
  const Model model = builder.Build();
  const CableNode& tip = model.nodes().back();
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 5e-4;
  settings.end_time = 1.0;
  State state = MakeInitialState(model);
  std::vector<double> deflection;
  std::vector<EnergyAccount> energy;
  const SolveResult result = SolveDynamic(
      model, settings, settings.time_step,
      [&](const State& s, const EnergyAccount& account) {
        deflection.push_back(s.q[tip.position_dof + 1]);
        energy.push_back(account);
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;

  // The record after 0.25 s (two periods; the higher modes have decayed by e^{−6 ζ₁ ω₁ t} < 1e-3).
  const std::size_t first = static_cast<std::size_t>(0.25 / settings.time_step);
  MatrixXd signal(deflection.size() - first, 1);
  for (std::size_t n = first; n < deflection.size(); ++n) signal(n - first, 0) = deflection[n];
  ModalIdentificationOptions options;
  options.extra_poles = 2;
  const ModalIdentification found = IdentifyModes(settings.time_step, signal, options);
  const double ei = kYoungs * std::pow(kSide, 4) / 12.0;
  const double omega_eb =
      1.87510407 * 1.87510407 * std::sqrt(ei / (kDensity * kSide * kSide)) / (kLength * kLength);
  const double omega = 2.0 * std::numbers::pi * found.modes[0].frequency;
  std::printf(
      "free decay: f1 %.4f Hz (Euler-Bernoulli %.4f Hz), zeta1 %.5f (tau omega / 2 = "
      "%.5f)\n",
      found.modes[0].frequency, omega_eb / (2.0 * std::numbers::pi), found.modes[0].damping_ratio,
      0.5 * tau * omega);
  // The decay's frequency is the model's first (8 elements: +0.3 % above Euler–Bernoulli).
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 1});
  ASSERT_TRUE(modes.converged) << modes.message;
  std::printf("free decay: first mode of the model %.4f Hz\n", modes.frequency_hz[0]);
  EXPECT_NEAR(omega, modes.omega[0], 1e-3 * modes.omega[0]);
  EXPECT_NEAR(omega, omega_eb, 5e-3 * omega_eb);
  EXPECT_NEAR(found.modes[0].damping_ratio, 0.5 * tau * omega, 0.01 * 0.5 * tau * omega);

  // Most of the launch energy is dissipated, and the account keeps it.
  const double launch = energy.front().Balance();
  double drift = 0.0;
  for (const EnergyAccount& e : energy) drift = std::max(drift, std::abs(e.Balance() - launch));
  std::printf("free decay: dissipated %.4f of the launch energy, largest drift %.2e of it\n",
              energy.back().dissipated / launch, drift / launch);
  EXPECT_GT(energy.back().dissipated, 0.9 * launch);
  EXPECT_LT(drift, 1e-3 * launch);
}

}  // namespace
}  // namespace ancfnet
