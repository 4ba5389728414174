// Nets whose threads are ANCF beams (NetSpec::beam_threads, `element: ancf_beam` on a net;
// issue 13):
//  - a cross of four pre-tensioned threads (natural length 0.999 of 0.5 m, 1 mm nylon, ideal
//    knots, free knot sections) with its four ends fixed and a 50 g knot mass at the centre,
//    under gravity. In the bending-free limit (EI/(T L²) ≈ 1e-4) the centre sinks to the δ of 4 T
//    sin θ = W, T = EA (L/(L₀ cos θ) − 1), tan θ = δ/L, W = (m + 2 ρA L) g (the centre takes half
//    of each thread's weight). The beam net, settled by dynamic relaxation (mass-proportional
//    Rayleigh damping), agrees with the cable net's static solution within 0.2 % and both with δ
//    within 1 % (Biot against Green strain and the threads' own sag differ by O(ε) ≈ 3e-3);
//  - a 3 × 3 beam net dropped onto a sphere from a scene (Carvalho–Martins contact with tanh
//    friction, Kelvin–Voigt damping of the beams, the midpoint rule, h = 0.25 ms, 0.2 s): the
//    balance kinetic + strain + gravity + dissipated − work stays within 1 % of the potential
//    energy the net releases (measured 0.10 %; with a ten times stiffer contact 0.8 %, and with
//    generalised-α ρ∞ = 0.9, h = 1 ms, 6 %, as for the same net of cables: the contact's
//    discretisation, not the beams).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/model/net_builder.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

constexpr double kArm = 0.5;        // m, centre to a fixed end
constexpr double kDiameter = 1e-3;  // m
constexpr double kYoungs = 1e9;     // Pa
constexpr double kDensity = 1000;   // kg/m³
constexpr double kKnotMass = 0.05;  // kg
constexpr double kRatio = 0.999;    // natural length / distance
constexpr double kGravity = 9.81;   // m/s²

// The cross; with `beams` its threads are beams, and Rayleigh α M settles it in dynamics.
Model MakeCross(bool beams) {
  const Material nylon{.youngs_modulus = kYoungs, .density = kDensity};
  NetSpec spec;
  spec.name = "cross";
  spec.topology = MakeGraphNet({Vector3d::Zero(), Vector3d(kArm, 0, 0), Vector3d(0, kArm, 0),
                                Vector3d(-kArm, 0, 0), Vector3d(0, -kArm, 0)},
                               {{0, 1}, {0, 2}, {0, 3}, {0, 4}});
  spec.thread = MakeCableProperties(nylon, MakeCircleSection(kDiameter));
  spec.elements_per_thread = 4;
  spec.natural_length_ratio = kRatio;
  spec.knot_masses = {{.knot = 0, .mass = kKnotMass}};
  if (beams)
    spec.beam_threads = BeamCableSpec{
        .material = {.youngs_modulus = kYoungs, .poisson_ratio = 0.4, .density = kDensity},
        .section = MakeCircleBeamSection(kDiameter, 0.4)};
  // The bending-free reference is a cross of hinged threads: the centre knot a ball joint. (A
  // knot that holds the sections keeps the threads straight across it, which over these 125 mm
  // elements lifts the centre by 2.9 %: the bending boundary layer √(EI/T) ≈ 5 mm is not
  // resolved.)
  spec.hold_knot_sections = false;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  AddNet(builder, spec);
  for (Index k = 1; k <= 4; ++k) builder.FixPointMass(KnotName("cross", k));
  if (beams) builder.SetRayleighDamping({.alpha = 60.0});
  return builder.Build();
}

// δ of 4 T sin θ = W, T = EA (L/(L₀ cos θ) − 1), by Newton on θ.
double CrossSag() {
  const double area = std::numbers::pi * kDiameter * kDiameter / 4.0;
  const double weight = (kKnotMass + 2.0 * kDensity * area * kArm) * kGravity;
  const double ea = kYoungs * area;
  const auto residual = [&](double theta) {
    return 4.0 * ea * (1.0 / (kRatio * std::cos(theta)) - 1.0) * std::sin(theta) - weight;
  };
  double theta = 0.05;
  for (int i = 0; i < 50; ++i) {
    const double h = 1e-7;
    theta -= residual(theta) / ((residual(theta + h) - residual(theta - h)) / (2 * h));
  }
  return kArm * std::tan(theta);
}

double CentreSag(const Model& model, const State& state) {
  return -state.q[model.point_masses()[model.FindPointMass(KnotName("cross", 0))].dof + 2];
}

TEST(BeamNet, CrossOfBeamThreadsSagsLikeTheCableCrossInTheBendingFreeLimit) {
  const Model cables = MakeCross(false);
  State cable_state = MakeInitialState(cables);
  StaticSettings statics;
  statics.load_steps = 4;
  const SolveResult solved = SolveStatic(
      cables, statics, [](const State&, const EnergyAccount&) {}, &cable_state);
  ASSERT_TRUE(solved.completed) << solved.message;

  const Model beams = MakeCross(true);
  ASSERT_EQ(beams.beam_elements().size(), 16u);
  DynamicSettings settings;
  settings.time_step = 1e-3;
  settings.end_time = 1.5;
  State beam_state = MakeInitialState(beams);
  double kinetic = 0.0;
  const SolveResult settled = SolveDynamic(
      beams, settings, 0.0, [&](const State&, const EnergyAccount& e) { kinetic = e.kinetic; },
      &beam_state);
  ASSERT_TRUE(settled.completed) << settled.message;

  const double expected = CrossSag();
  const double cable_sag = CentreSag(cables, cable_state);
  const double beam_sag = CentreSag(beams, beam_state);
  std::printf(
      "cross: sag of the beam net %.6f m, of the cable net %.6f m, bending-free %.6f m; "
      "kinetic energy left %.2e J\n",
      beam_sag, cable_sag, expected, kinetic);
  EXPECT_LT(kinetic, 1e-9 * kKnotMass * kGravity * expected);  // at rest
  EXPECT_NEAR(beam_sag, cable_sag, 2e-3 * cable_sag);
  EXPECT_NEAR(cable_sag, expected, 1e-2 * expected);
  EXPECT_NEAR(beam_sag, expected, 1e-2 * expected);
}

constexpr const char* kDropScene = R"(gravity: [0, 0, -9.81]
materials:
  nylon: {youngs_modulus: 1.0e9, density: 1000, poisson_ratio: 0.4, axial_damping_time: 1.0e-4,
          bending_damping_time: 1.0e-4}
sections:
  thread: {shape: circle, diameter: 0.002}
nets:
  - name: net
    type: square
    element: ancf_beam
    side: 0.6
    meshes: 3
    elements_per_thread: 1
    center: [0, 0, 0.33]
    material: nylon
    section: thread
    knot_model: ideal
    knot_mass: 0.002
contact:
  law: {type: carvalho_martins, stiffness: 1.0e5, restitution: 0.3}
  friction: {type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-2}
  points_per_element: 8
  targets:
    - {name: ball, type: sphere, center: [0, 0, 0], radius: 0.3}
analysis:
  type: dynamic
  integrator: midpoint
  time_step: 2.5e-4
  end_time: 0.2
)";

TEST(BeamNet, BeamNetDroppedOnASphereKeepsItsEnergyBalance) {
  const Scene scene = ParseScene(kDropScene);
  const Model& model = scene.model;
  ASSERT_EQ(model.beam_elements().size(), 24u);
  State state = MakeInitialState(model);
  double balance0 = 0.0, gravity0 = 0.0, released = 0.0, max_drift = 0.0, dissipated = 0.0;
  bool first = true;
  const SolveResult result = SolveDynamic(
      model, scene.analysis.dynamics, scene.analysis.dynamics.time_step,
      [&](const State&, const EnergyAccount& e) {
        if (first) {
          balance0 = e.Balance();
          gravity0 = e.gravity;
        }
        first = false;
        released = std::max(released, gravity0 - e.gravity);
        max_drift = std::max(max_drift, std::abs(e.Balance() - balance0));
        dissipated = e.dissipated;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  std::printf("beam net drop: released %.4e J, dissipated %.4e J, largest drift %.3f %%\n",
              released, dissipated, 100.0 * max_drift / released);
  EXPECT_GT(released, 0.0);
  EXPECT_GT(dissipated, 0.0);
  EXPECT_LT(max_drift, 0.01 * released);
}

}  // namespace
}  // namespace ancfnet
