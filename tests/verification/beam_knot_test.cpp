// Knots that hold the sections of beam threads (section locks, forces/section_lock.hpp; issue 13):
// two beam threads in series, joined at a knot of a graph net, carry an end torque and a torsion
// mode across it.
//  - Saint-Venant torsion of the square aluminium bar of examples/beam_torsion.yaml (L = 1 m,
//    a = 10 mm, T = 10 N m) made of two 0.5 m threads through a knot whose lock has the
//    stiffness k = GJ/(0.1 m): the end turns by φ = T L/(GJ) + asin(T/k) (the lock stores
//    k (1 − cos θ), so its torque is k sin θ), within 10⁻³; the jump across the knot is
//    asin(T/k) within 1 %. With the default lock (100 GJ/L_e) the end turns by TL/(GJ) within
//    0.2 %. With free knot sections the second thread would spin freely (singular statics).
//  - the clamped–free steel shaft (L = 1 m, d = 50 mm) of two threads through a knot with the
//    default lock: first torsion frequency f = (1/4L) √(G/ρ) (Blevins 1979, table 8-19) within
//    1 %, found among the modes by its turn of d₂ at the tip.
//  - energy: the bar, its second thread spinning at 20 rad/s about its axis at t = 0 and the
//    first at rest: the knot passes the spin on (the first thread's end turns by more than 0.01
//    rad) and T + U − W, the lock's energy in U, stays within 0.5 % of the launch energy
//    (generalised-α, ρ∞ = 1).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ancfnet/forces/section_lock_forces.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "ancfnet/solvers/static_solver.hpp"

namespace ancfnet {
namespace {

// Two collinear beam threads net.t0 (x = 0 … L/2) and net.t1 (x = L/2 … L) joined at knot
// net.k1, d₂ along y; `lock` holds the knot sections (empty: the default lock), `extra`
// follows.
std::string SeriesBar(const std::string& material, const std::string& section, double length,
                      int elements, const std::string& lock, const std::string& extra) {
  return fmt::format(R"(gravity: [0, 0, 0]
materials:
  {0}
sections:
  {1}
nets:
  - name: net
    type: graph
    element: ancf_beam
    knot_positions: [[0, 0, 0], [{2}, 0, 0], [{3}, 0, 0]]
    threads: [[0, 1], [1, 2]]
    axis: [0, 1, 0]
    elements_per_thread: {4}
    material: m
    section: s
{5}constraints:
  - {{type: clamp, at: net.t0.start}}
{6})",
                     material, section, 0.5 * length, length, elements, lock, extra);
}

const char* kAluminium = "m: {youngs_modulus: 71.7e9, density: 2700, poisson_ratio: 0.33}";
const char* kSquare = "s: {shape: rectangle, width: 0.01, height: 0.01}";
const char* kTorque = R"(loads:
  - {type: point_moment, at: net.t1.end, moment: [10, 0, 0]}
analysis:
  type: static
  load_steps: 2
)";

// The node at fraction s of a cable.
const CableNode& Node(const Model& model, const std::string& cable, double s) {
  return model.nodes()[model.LocateCableNode(model.FindCable(cable), s)];
}

// Twist about x of a node whose d₂ started along y.
double Twist(const Model& model, const VectorXd& q, const std::string& cable, double s) {
  const Vector3d d2 = q.segment<3>(Node(model, cable, s).section_dof);
  return std::atan2(d2.z(), d2.y());
}

State SolveStaticScene(const Scene& scene) {
  State state = MakeInitialState(scene.model);
  const SolveResult result = SolveStatic(
      scene.model, scene.analysis.statics, [](const State&, const EnergyAccount&) {}, &state);
  EXPECT_TRUE(result.completed) << result.message;
  return state;
}

TEST(BeamKnot, EndTorqueIsCarriedThroughTheKnotOfTwoThreadsInSeries) {
  const double torque = 10.0;
  // GJ from the model: J = 0.1406 a⁴ by the Saint-Venant series (model/beam_section.hpp).
  const Scene probe = ParseScene(SeriesBar(kAluminium, kSquare, 1.0, 4, "", kTorque));
  const double gj = probe.model.beam_elements()[0].parameters.torsional_stiffness;
  ASSERT_EQ(probe.model.section_locks().size(), 1u);  // knot 1 only: 0 and 2 hold one thread

  const double k = gj / 0.1;
  const Scene scene = ParseScene(SeriesBar(
      kAluminium, kSquare, 1.0, 4, fmt::format("    knot_section_stiffness: {}\n", k), kTorque));
  ASSERT_EQ(scene.model.section_locks()[0].stiffness, k);
  const State state = SolveStaticScene(scene);
  const Model& model = scene.model;
  const double end = Twist(model, state.q, "net.t1", 1.0);
  const double jump = Twist(model, state.q, "net.t1", 0.0) - Twist(model, state.q, "net.t0", 1.0);
  const double expected_jump = std::asin(torque / k);
  const double expected = torque * 1.0 / gj + expected_jump;
  std::printf(
      "beam knot: end twist %.6f rad (TL/GJ + asin(T/k) = %.6f rad), jump at the knot %.6f rad "
      "(asin(T/k) = %.6f rad)\n",
      end, expected, jump, expected_jump);
  EXPECT_NEAR(end, expected, 1e-3 * expected);
  EXPECT_NEAR(jump, expected_jump, 1e-2 * expected_jump);

  const State stiff = SolveStaticScene(probe);
  const double stiff_end = Twist(probe.model, stiff.q, "net.t1", 1.0);
  std::printf("beam knot, default lock (k = %.4g N m/rad): end twist %.6f rad (TL/GJ %.6f rad)\n",
              probe.model.section_locks()[0].stiffness, stiff_end, torque / gj);
  EXPECT_NEAR(stiff_end, torque / gj, 2e-3 * torque / gj);
}

TEST(BeamKnot, TorsionModeOfAShaftRunsThroughTheKnot) {
  const Scene scene =
      ParseScene(SeriesBar("m: {youngs_modulus: 2.0e11, density: 7800, poisson_ratio: 0.3}",
                           "s: {shape: circle, diameter: 0.05}", 1.0, 8, "", ""));
  const Model& model = scene.model;
  const ModalResult modes = CalcModes(model, model.initial_positions(), {.num_modes = 10});
  ASSERT_TRUE(modes.converged) << modes.message;
  const Index d2_z = Node(model, "net.t1", 1.0).section_dof + 2;
  Eigen::Index torsion = 0;
  for (Eigen::Index i = 1; i < modes.shapes.cols(); ++i)
    if (std::abs(modes.shapes(d2_z, i)) > std::abs(modes.shapes(d2_z, torsion))) torsion = i;
  const double expected = std::sqrt(2.0e11 / (2.0 * 1.3) / 7800.0) / 4.0;
  std::printf("shaft through a knot: torsion mode %ld at %.2f Hz (closed form %.2f Hz)\n",
              static_cast<long>(torsion), modes.frequency_hz[torsion], expected);
  EXPECT_NEAR(modes.frequency_hz[torsion], expected, 0.01 * expected);
}

struct SpinRun {
  double launch = 0.0;          // kinetic energy at t = 0 (J)
  double max_drift = 0.0;       // max |balance(t) − balance(0)| (J)
  double max_lock = 0.0;        // largest energy in the section locks (J)
  double max_knot_twist = 0.0;  // largest turn of the first thread's end about x (rad)
};

// The bar of two threads, the second spinning at 20 rad/s about x at t = 0; `lock` as SeriesBar.
SpinRun SpinSecondThread(const std::string& lock) {
  const Scene scene = ParseScene(SeriesBar(kAluminium, kSquare, 1.0, 4, lock, R"(analysis:
  type: dynamic
  integrator: generalized_alpha
  spectral_radius: 1.0
  time_step: 1.0e-5
  end_time: 0.004
)"));
  const Model& model = scene.model;
  State state = MakeInitialState(model);
  // The second thread's sections spin at ω about x: ḋ₂ = ω × d₂, ḋ₃ = ω × d₃.
  const Vector3d omega(20.0, 0.0, 0.0);
  const Cable& second = model.cables()[model.FindCable("net.t1")];
  for (Index n = second.first_node; n <= second.first_node + second.num_elements; ++n)
    for (const Index dof : {model.nodes()[n].section_dof, model.nodes()[n].section_dof + 3})
      state.v.segment<3>(dof) = omega.cross(Vector3d(state.q.segment<3>(dof)));
  SpinRun run;
  double balance0 = 0.0;
  bool first = true;
  const SolveResult result = SolveDynamic(
      model, scene.analysis.dynamics, 0.0,
      [&](const State& s, const EnergyAccount& e) {
        if (first) {
          run.launch = e.kinetic;
          balance0 = e.Balance();
        }
        first = false;
        run.max_drift = std::max(run.max_drift, std::abs(e.Balance() - balance0));
        run.max_lock = std::max(run.max_lock, CalcSectionLockEnergy(model, s.q));
        run.max_knot_twist =
            std::max(run.max_knot_twist, std::abs(Twist(model, s.q, "net.t0", 1.0)));
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  return run;
}

TEST(BeamKnot, SpinPassesThroughTheKnotWithTheEnergyBalanced) {
  const SpinRun held = SpinSecondThread("");
  const SpinRun free = SpinSecondThread("    knot_sections: free\n");
  std::printf(
      "spin through a knot: launch %.4e J, largest lock energy %.3e J, first thread's end turned "
      "%.4f rad (free knot: %.1e rad), drift %.2e of the launch energy\n",
      held.launch, held.max_lock, held.max_knot_twist, free.max_knot_twist,
      held.max_drift / held.launch);
  EXPECT_GT(held.launch, 0.0);
  EXPECT_GT(held.max_lock, 1e-3 * held.launch);
  EXPECT_GT(held.max_knot_twist, 1e-3);
  EXPECT_LT(free.max_knot_twist, 1e-9);  // a ball joint passes no spin on
  EXPECT_LT(held.max_drift, 5e-3 * held.launch);
}

}  // namespace
}  // namespace ancfnet
