// ANCF beams in dynamics, from scene text (issue 13):
//  - energy balance: a steel cantilever of beam elements, spinning about its axis at t = 0 (the
//    root held), swings under gravity and twists; T + U + V − W (the sections' spin in T) stays
//    within 1 % of the largest kinetic energy with the undamped trapezoidal rule (ρ∞ = 1). (Not
//    a step end torque: a moment of fixed direction is not conservative in 3D (Ziegler 1968), and
//    undamped runs with one grew without bound; docs/validation.md, "ANCF beams in scenes");
//  - contact: a beam laid on a plane comes to rest on it and the contact force carries its
//    weight within 2 % (the contact inspects the beam's centre line, the cable's Hermite curve).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "spinning_beam_cantilever.hpp"

namespace ancfnet {
namespace {

TEST(BeamDynamics, SwingingAndTwistingCantileverKeepsTheEnergyBalance) {
  const Scene scene = ParseScene(std::string(verification::kSpinningBeamCantilever) + R"(analysis:
  type: dynamic
  integrator: generalized_alpha
  spectral_radius: 1.0
  time_step: 1.0e-4
  end_time: 0.05
)");
  State state = MakeInitialState(scene.model);
  double balance0 = 0.0, max_kinetic = 0.0, max_drift = 0.0, max_twist = 0.0;
  bool first = true;
  const SolveResult result = SolveDynamic(
      scene.model, scene.analysis.dynamics, 0.0,
      [&](const State& s, const EnergyAccount& e) {
        if (first) balance0 = e.Balance();
        first = false;
        max_kinetic = std::max(max_kinetic, e.kinetic);
        max_drift = std::max(max_drift, std::abs(e.Balance() - balance0));
        max_twist = std::max(max_twist, std::abs(verification::TipTwist(scene.model, s)));
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  std::printf("beam dynamics: max kinetic %.5f J, max |drift| %.3e J, largest twist %.4f rad\n",
              max_kinetic, max_drift, max_twist);
  EXPECT_GT(max_twist, 0.002);  // it twists and untwists: the spin is in r_y, r_z
  EXPECT_LT(max_drift, 0.01 * max_kinetic);
}

TEST(BeamDynamics, BeamOnAPlaneRestsWithTheContactForceCarryingItsWeight) {
  const Scene scene = ParseScene(R"(gravity: [0, 0, -9.81]
materials:
  steel: {youngs_modulus: 2.0e11, density: 7800, poisson_ratio: 0.3}
sections:
  rod: {shape: circle, diameter: 0.01}
cables:
  - {name: rod, element: ancf_beam, orientation: [0, 1, 0], start: [0, 0, 0.005],
     end: [1, 0, 0.005], elements: 8, material: steel, section: rod}
contact:
  law: {stiffness: 1.0e9, restitution: 0.3}
  friction: {type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-3}
  targets:
    - {name: ground, type: plane, point: [0, 0, 0], normal: [0, 0, 1]}
analysis:
  type: dynamic
  time_step: 1.0e-4
  end_time: 0.05
)");
  State state = MakeInitialState(scene.model);
  const SolveResult result = SolveDynamic(
      scene.model, scene.analysis.dynamics, 0.0, [](const State&, const EnergyAccount&) {},
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  const TargetContact::Summary s =
      TargetContact(scene.model).Summarize(state.q, state.v, state.contact_history);
  const double weight = 7800.0 * std::numbers::pi * 0.25 * 1e-4 * 9.81;
  std::printf("beam on a plane: %d touching, N = %.4f N (weight %.4f N), deepest %.2e m\n",
              s.active, s.normal_force, weight, s.max_penetration);
  EXPECT_GT(s.active, 8);
  EXPECT_NEAR(s.normal_force, weight, 0.02 * weight);
}

}  // namespace
}  // namespace ancfnet
