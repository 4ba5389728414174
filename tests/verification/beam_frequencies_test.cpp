// Natural frequencies of the linearised ANCF cable against Euler–Bernoulli beam theory
// (Blevins 1979, "Formulas for natural frequency and mode shape", table 8-1): cantilever,
// pinned–pinned and free–free beams, the first five bending modes; a taut string; an axial rod.
// The cable bends in two planes alike, so bending modes come in equal pairs.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "ancfnet/forces/forces.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

constexpr double kLength = 1.0;
const Material kSteel{.youngs_modulus = 2.0e11, .density = 7800.0};
const Section kBar = MakeRectangleSection(0.01, 0.01);

// √(EI/(ρA L⁴)) (rad/s).
double BeamFrequencyScale() {
  const CableProperties p = MakeCableProperties(kSteel, kBar);
  return std::sqrt(p.bending_stiffness / (p.mass_per_length * std::pow(kLength, 4)));
}

enum class Supports { kClampedFree, kPinnedPinned, kFreeFree };

Model MakeBeam(Supports supports, int elements) {
  ModelBuilder builder;
  builder.AddCable({.name = "beam",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(kLength, 0.0, 0.0),
                    .num_elements = elements,
                    .properties = MakeCableProperties(kSteel, kBar)});
  if (supports == Supports::kClampedFree) builder.AddClamp({"beam", 0.0});
  if (supports == Supports::kPinnedPinned) {
    builder.AddPin({"beam", 0.0});
    builder.AddPin({"beam", 1.0});
  }
  return builder.Build();
}

// (β_n L)² of the first five bending modes.
std::array<double, 5> EulerBernoulli(Supports supports) {
  const auto squared = [](std::array<double, 5> beta) {
    for (double& b : beta) b *= b;
    return beta;
  };
  switch (supports) {
    case Supports::kClampedFree:
      return squared({1.875104069, 4.694091133, 7.854757438, 10.99554073, 14.13716839});
    case Supports::kPinnedPinned:
      return squared({std::numbers::pi, 2 * std::numbers::pi, 3 * std::numbers::pi,
                      4 * std::numbers::pi, 5 * std::numbers::pi});
    case Supports::kFreeFree:
      return squared({4.730040745, 7.853204624, 10.99560784, 14.13716549, 17.27875966});
  }
  return {};
}

// Relative errors of the first five bending frequencies (each the mean of its pair), checking
// that the pairs are equal and, free–free, that the 5 rigid modes come first.
std::array<double, 5> BendingErrors(Supports supports, int elements) {
  const Model model = MakeBeam(supports, elements);
  const int rigid = supports == Supports::kFreeFree ? 5 : 0;
  // Pinned–pinned: the cable's axial and the (torsion-free) rigid rotation about x are absent;
  // only bending pairs come first for this slender bar (axial ω₁ ≫ bending ω₅).
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = rigid + 10});
  EXPECT_TRUE(modes.converged) << modes.message;
  for (int i = 0; i < rigid; ++i) {
    EXPECT_TRUE(modes.rigid[i]);
    EXPECT_EQ(modes.omega[i], 0.0);
  }
  const std::array<double, 5> exact = EulerBernoulli(supports);
  std::array<double, 5> errors{};
  for (int n = 0; n < 5; ++n) {
    const double a = modes.omega[rigid + 2 * n], b = modes.omega[rigid + 2 * n + 1];
    EXPECT_NEAR(a, b, 1e-6 * a) << "pair " << n;
    errors[n] = 0.5 * (a + b) / (exact[n] * BeamFrequencyScale()) - 1.0;
  }
  return errors;
}

class BeamFrequencies : public ::testing::TestWithParam<Supports> {};

TEST_P(BeamFrequencies, MatchEulerBernoulliAndConverge) {
  // Measured in docs/validation.md ("Beam frequencies"); 16 elements are within 0.5 % for five
  // modes, and the error falls by about 16 per halving (fourth order in the element length).
  const std::array<double, 5> coarse = BendingErrors(GetParam(), 8);
  const std::array<double, 5> fine = BendingErrors(GetParam(), 16);
  for (int n = 0; n < 5; ++n) {
    std::printf("mode %d: error %.3e (8 elements), %.3e (16)\n", n + 1, coarse[n], fine[n]);
    EXPECT_LT(std::abs(fine[n]), 5e-3) << "mode " << n + 1;
    EXPECT_GE(fine[n], -1e-9);  // a conforming discretisation is stiffer than the beam
    if (std::abs(fine[n]) > 1e-7) {
      EXPECT_GT(coarse[n] / fine[n], 8.0) << "mode " << n + 1;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Supports, BeamFrequencies,
                         ::testing::Values(Supports::kClampedFree, Supports::kPinnedPinned,
                                           Supports::kFreeFree),
                         [](const auto& info) {
                           switch (info.param) {
                             case Supports::kClampedFree:
                               return "ClampedFree";
                             case Supports::kPinnedPinned:
                               return "PinnedPinned";
                             case Supports::kFreeFree:
                               return "FreeFree";
                           }
                           return "";
                         });

TEST(ModalAnalysis, ShapesAreMassNormalised) {
  const Model model = MakeBeam(Supports::kClampedFree, 8);
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 6});
  ASSERT_TRUE(modes.converged);
  // φᵢᵀ M φⱼ = δᵢⱼ with M assembled over all coordinates (φ is 0 on the fixed ones), and
  // φᵢᵀ K φⱼ = ω² δᵢⱼ.
  const MatrixXd& phi = modes.shapes;
  ASSERT_EQ(phi.rows(), model.num_dofs());
  for (int i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) {
      EXPECT_EQ(phi.row(i).norm(), 0.0);
    }
  }
  const DofMap all = DofMap::AllCoordinates(model);
  Workspace ws(model);
  SystemMatrix mass(model, all), stiffness(model, all);
  AssembleMassMatrix(model, ws, &mass);
  AssembleIterationMatrix(model, model.initial_positions(), VectorXd::Zero(model.num_dofs()),
                          {.mass = 0.0, .damping = 0.0, .stiffness = 1.0}, 1.0, ws, &stiffness);
  const MatrixXd modal_mass = phi.transpose() * (mass.matrix() * phi);
  const MatrixXd modal_stiffness = phi.transpose() * (stiffness.matrix() * phi);
  EXPECT_LT((modal_mass - MatrixXd::Identity(6, 6)).norm(), 1e-9);
  const MatrixXd lambda = modes.omega.array().square().matrix().asDiagonal();
  EXPECT_LT((modal_stiffness - lambda).norm(), 1e-8 * lambda.norm());
}

// A string pre-tensioned between two pins: the cable's natural length L₀ is shorter than the
// span, so it starts uniformly stretched with N = EA (λ² − 1)/2. Transverse waves travel at
// √(N/ρA) in the reference coordinate, so f_n = n/(2 L₀) √(N/ρA) (with EI ≈ 0).
TEST(ModalAnalysis, TautStringFrequencies) {
  const Material wire{.youngs_modulus = 1e9, .density = 1000.0};
  CableProperties p = MakeCableProperties(wire, MakeCircleSection(0.001));
  p.bending_stiffness *= 1e-6;  // a string
  const double stretch = 1.001, natural = 2.0;
  ModelBuilder builder;
  builder.AddCable({.name = "string",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(stretch * natural, 0, 0),
                    .num_elements = 40,
                    .properties = p,
                    .natural_length = natural});
  builder.AddPin({"string", 0.0});
  builder.AddPin({"string", 1.0});
  const Model model = builder.Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 10});
  ASSERT_TRUE(modes.converged) << modes.message;
  const double n_axial = p.axial_stiffness * 0.5 * (stretch * stretch - 1.0);
  for (int n = 1; n <= 5; ++n) {
    const double exact = n / (2.0 * natural) * std::sqrt(n_axial / p.mass_per_length);
    const double f = 0.5 * (modes.frequency_hz[2 * n - 2] + modes.frequency_hz[2 * n - 1]);
    EXPECT_NEAR(f / exact, 1.0, 5e-3) << "mode " << n;
  }
}

// An axial rod clamped at one end, its transverse motion fixed: f_n = (2n − 1)/(4L) √(E/ρ).
TEST(ModalAnalysis, AxialRodFrequencies) {
  const int elements = 40;
  ModelBuilder builder;
  builder.AddCable({.name = "rod",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(kLength, 0, 0),
                    .num_elements = elements,
                    .properties = MakeCableProperties(kSteel, kBar)});
  builder.AddClamp({"rod", 0.0});
  for (int i = 1; i <= elements; ++i)
    builder.FixCoordinates({"rod", static_cast<double>(i) / elements},
                           {false, true, true, false, true, true});
  const Model model = builder.Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 5});
  ASSERT_TRUE(modes.converged) << modes.message;
  for (int n = 1; n <= 5; ++n) {
    const double exact =
        (2 * n - 1) / (4.0 * kLength) * std::sqrt(kSteel.youngs_modulus / kSteel.density);
    EXPECT_NEAR(modes.frequency_hz[n - 1] / exact, 1.0, 5e-3) << "mode " << n;
  }
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

// Kelvin–Voigt bending damping σ = E (κ + τ κ̇) gives every bending mode ζ = ω τ / 2, the exact
// value for a material whose damping matrix is τ K_bending.
TEST(ModalAnalysis, KelvinVoigtBendingDampingRatios) {
  const double tau = 2e-4;
  Material damped = kSteel;
  damped.bending_damping_time = tau;
  ModelBuilder builder;
  builder.AddCable({.name = "beam",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(kLength, 0.0, 0.0),
                    .num_elements = 16,
                    .properties = MakeCableProperties(damped, kBar)});
  builder.AddClamp({"beam", 0.0});
  const Model model = builder.Build();
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 8});
  ASSERT_TRUE(modes.converged) << modes.message;
  for (int i = 0; i < 8; ++i)
    EXPECT_NEAR(modes.damping_ratio[i], 0.5 * modes.omega[i] * tau, 1e-6 * modes.omega[i] * tau)
        << "mode " << i + 1;
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

// Linearised about a static equilibrium: a string pinned at one end and pulled at the other by a
// 10 N axial force (its end free only along the axis). Solving N λ = T with the Green strain law
// N = EA (λ² − 1)/2 gives the tension; the transverse modes are then f_n = n/(2 L₀) √(N/ρA).
TEST(ModalAnalysis, AboutAStaticEquilibriumUnderTension) {
  const Material wire{.youngs_modulus = 1e9, .density = 1000.0};
  CableProperties p = MakeCableProperties(wire, MakeCircleSection(0.001));
  p.bending_stiffness *= 1e-6;
  const double length = 2.0, pull = 10.0;
  ModelBuilder builder;
  builder.AddCable({.name = "string",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(length, 0, 0),
                    .num_elements = 40,
                    .properties = p});
  builder.AddPin({"string", 0.0});
  builder.FixCoordinates({"string", 1.0}, {false, true, true, false, false, false});
  builder.AddPointForce({"string", 1.0}, Vector3d(pull, 0, 0));
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  ASSERT_TRUE(SolveStatic(
                  model, {}, [](const State&, const EnergyAccount&) {}, &state)
                  .completed);
  // λ³ − λ = 2T/EA by Newton.
  double stretch = 1.0;
  for (int i = 0; i < 50; ++i)
    stretch -= (stretch * stretch * stretch - stretch - 2 * pull / p.axial_stiffness) /
               (3 * stretch * stretch - 1);
  const double tension = pull / stretch;  // N (second Piola–Kirchhoff)
  ASSERT_NEAR(state.q[model.NodePositionDof(model.num_nodes() - 1)], stretch * length, 1e-9);
  const ModalResult modes = CalcModes(model, state.q, {.num_modes = 10});
  ASSERT_TRUE(modes.converged) << modes.message;
  // The first four transverse pairs (the first axial mode, near (1/4L) √(EA/ρA) = 125 Hz, comes
  // before the fifth).
  for (int n = 1; n <= 4; ++n) {
    const double exact = n / (2.0 * length) * std::sqrt(tension / p.mass_per_length);
    EXPECT_NEAR(modes.frequency_hz[2 * n - 2] / exact, 1.0, 5e-3) << "mode " << n;
    EXPECT_NEAR(modes.frequency_hz[2 * n - 1] / exact, 1.0, 5e-3) << "mode " << n;
  }
  // About the unloaded reference the string is slack: no transverse stiffness but bending.
  const ModalResult slack = CalcModes(model, model.initial_positions(), {.num_modes = 2});
  ASSERT_TRUE(slack.converged) << slack.message;
  EXPECT_LT(slack.frequency_hz[0], 0.1 * modes.frequency_hz[0]);
}

}  // namespace
}  // namespace ancfnet
