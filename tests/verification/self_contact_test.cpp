// Self-contact through the full solver: a thread driven across a taut one deflects it and never
// passes through; a 2 mm thread shot at 20 m/s onto another with the default search settings
// does not tunnel; a coiled rope falling on a plane piles up without passing through itself.

#include "ancfnet/forces/self_contact.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kRadius = 0.001;  // a 2 mm thread

CableProperties Thread() {
  Material nylon{.youngs_modulus = 3e9,
                 .density = 1140,
                 .axial_damping_time = 1e-4,
                 .bending_damping_time = 1e-4};
  CableProperties p = MakeCableProperties(nylon, MakeCircleSection(2 * kRadius));
  p.radius = kRadius;
  return p;
}

ContactSpec SelfContactSpec(double stiffness = 1e8) {
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, stiffness, 0.5);
  spec.friction = MakeTanhFriction(0.2, 0.2, 1e-2, 1e-1);
  spec.self_contact = true;
  spec.point_mass_radius = kRadius;
  return spec;
}

// Thread a along x pinned at both ends; thread b along y above it. Tracks the vertical gap of
// their middles (where they cross, by symmetry) and the deepest self-contact penetration.
struct Crossing {
  SolveResult result;
  double min_separation = 1e9;  // z_b − z_a at the middles (m)
  double max_penetration = 0.0;
  double final_deflection = 0.0;  // of a's middle (m)
  VectorXd q;                     // at the end
};

Crossing RunCrossing(bool driven, double speed, double end_time, DynamicSettings settings,
                     double stiffness = 1e8) {
  const CableProperties p = Thread();
  ModelBuilder builder;
  builder.AddCable({.name = "a",
                    .start = Vector3d(-0.5, 0, 0),
                    .end = Vector3d(0.5, 0, 0),
                    .num_elements = 10,
                    .properties = p,
                    .natural_length = 0.999});
  builder.AddPin({"a", 0.0});
  builder.AddPin({"a", 1.0});
  const double z = 2 * kRadius + 0.005;
  builder.AddPointMass("b0", driven ? 0.0 : 1e-4, Vector3d(0, -0.25, z));
  builder.AddPointMass("b1", driven ? 0.0 : 1e-4, Vector3d(0, 0.25, z));
  builder.AddCable({.name = "b",
                    .start = Vector3d(0, -0.25, z),
                    .end = Vector3d(0, 0.25, z),
                    .num_elements = 10,
                    .properties = p,
                    .start_knot = "b0",
                    .end_knot = "b1"});
  if (driven) {
    builder.MovePointMass("b0", Vector3d(0, 0, -speed));
    builder.MovePointMass("b1", Vector3d(0, 0, -speed));
  } else {
    builder.SetInitialVelocity("b", Vector3d(0, 0, -speed));
    builder.SetPointMassVelocity("b0", Vector3d(0, 0, -speed));
    builder.SetPointMassVelocity("b1", Vector3d(0, 0, -speed));
  }
  builder.SetContact(SelfContactSpec(stiffness));
  const Model model = builder.Build();
  settings.end_time = end_time;
  const Index a_middle = model.NodePositionDof(model.LocateCableNode(model.FindCable("a"), 0.5));
  const Index b_middle = model.NodePositionDof(model.LocateCableNode(model.FindCable("b"), 0.5));
  SelfContact watch(model);
  Crossing c;
  State state = MakeInitialState(model);
  c.result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        c.min_separation = std::min(c.min_separation, s.q[b_middle + 2] - s.q[a_middle + 2]);
        watch.FindCandidates(s, 0.0);
        c.max_penetration = std::max(c.max_penetration, watch.Summarize(s.q, s.v).max_penetration);
      },
      &state);
  c.final_deflection = -state.q[a_middle + 2];
  c.q = state.q;
  return c;
}

TEST(SelfContact, ThreadDrivenAcrossATautThreadNeverPassesThrough) {
  // b's ends move down 8.5 cm: b drapes over a and carries it down by several centimetres.
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 1e-4;
  const Crossing c = RunCrossing(true, 1.0, 0.085, settings);
  ASSERT_TRUE(c.result.completed) << c.result.message;
  std::printf(
      "driven crossing: a deflected %.4f m, closest middles %.5f m (2r = %.4f), deepest "
      "%.2e m\n",
      c.final_deflection, c.min_separation, 2 * kRadius, c.max_penetration);
  EXPECT_GT(c.final_deflection, 0.03);
  EXPECT_GT(c.min_separation, 2 * kRadius - 0.1 * kRadius);
  EXPECT_LT(c.max_penetration, 0.1 * kRadius);
}

TEST(SelfContact, ThreadShotAt20MetresPerSecondDoesNotTunnel) {
  // 5 mm apart, closing at 20 m/s. With the default settings (generalised-α, h = 1 ms) a step
  // would carry the thread 10 diameters; with the midpoint rule at 0.1 ms, one diameter.
  DynamicSettings midpoint;
  midpoint.integrator = IntegratorType::kImplicitMidpoint;
  midpoint.time_step = 1e-4;
  for (const DynamicSettings& settings : {DynamicSettings{}, midpoint}) {
    const Crossing c = RunCrossing(false, 20.0, 0.004, settings);
    ASSERT_TRUE(c.result.completed) << c.result.message;
    std::printf(
        "20 m/s impact, h = %g s: closest middles %.5f m (2r = %.4f), deepest %.2e m, "
        "%ld cut steps\n",
        settings.time_step, c.min_separation, 2 * kRadius, c.max_penetration,
        c.result.statistics.step_cuts);
    EXPECT_GT(c.min_separation, 2 * kRadius - 0.5 * kRadius);
    EXPECT_LT(c.max_penetration, 0.5 * kRadius);
  }
}

// A contact law far too soft to stop the thread: the run stops with the reason instead of letting
// it through.
TEST(SelfContact, TooSoftAContactStopsTheRunInsteadOfLettingThreadsThrough) {
  const Crossing c = RunCrossing(false, 20.0, 0.004, DynamicSettings{}, 1e3);
  EXPECT_FALSE(c.result.completed);
  EXPECT_NE(c.result.message.find("self-contact"), std::string::npos) << c.result.message;
  EXPECT_GT(c.min_separation, 0.0);
}

// A rope coiled in a helix (4 turns of 3 cm radius, 5 mm pitch: 48 one-element threads joined
// at massless knots) falls 1 cm onto a plane and piles up: its turns land on each other, never
// pass through each other (a step that would is rejected), no pair overlaps by more than a fifth
// of the radius, nothing sinks into the plane, and it loses energy as it settles.
Model MakeCoiledRope() {
  const CableProperties p = Thread();
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -9.81));
  constexpr int kSegments = 48, kPerTurn = 12;
  auto helix = [](int k) {
    const double phi = 2.0 * std::numbers::pi * k / kPerTurn;
    return Vector3d(0.03 * std::cos(phi), 0.03 * std::sin(phi), 0.01 + 0.005 * k / kPerTurn);
  };
  for (int k = 0; k <= kSegments; ++k) builder.AddPointMass(fmt::format("k{}", k), 0.0, helix(k));
  for (int k = 0; k < kSegments; ++k)
    builder.AddCable({.name = fmt::format("s{}", k),
                      .start = helix(k),
                      .end = helix(k + 1),
                      .num_elements = 1,
                      .properties = p,
                      .start_knot = fmt::format("k{}", k),
                      .end_knot = fmt::format("k{}", k + 1)});
  // Softer than the impact tests' law: with 1e8 the landing impacts of these light threads
  // last 20 µs, shorter than any step here, and an unresolved stiff impact can gain energy.
  ContactSpec spec = SelfContactSpec(1e6);
  ContactTarget ground;
  ground.name = "ground";
  spec.targets.push_back(ground);
  builder.SetContact(spec);
  return builder.Build();
}

TEST(SelfContact, CoiledRopeFallingOnAPlanePilesUpWithoutCrossingItself) {
  const Model model = MakeCoiledRope();
  DynamicSettings settings;
  settings.time_step = 2e-4;
  settings.end_time = 0.25;
  SelfContact watch(model);
  double deepest = 0.0, max_kinetic = 0.0, final_kinetic = 0.0;
  int most_active = 0;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount& e) {
        watch.FindCandidates(s, 0.0);
        const SelfContact::Summary sum = watch.Summarize(s.q, s.v);
        deepest = std::max(deepest, sum.max_penetration);
        most_active = std::max(most_active, sum.active);
        max_kinetic = std::max(max_kinetic, e.kinetic);
        final_kinetic = e.kinetic;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  double lowest = 1.0;
  for (const PointMass& knot : model.point_masses())
    lowest = std::min(lowest, state.q[knot.dof + 2]);
  std::printf(
      "coiled rope: lowest knot at z = %.5f m, up to %d touching pairs, deepest %.2e m, "
      "kinetic energy %.2e J at the end (largest %.2e J), %ld steps, %ld cut\n",
      lowest, most_active, deepest, final_kinetic, max_kinetic, result.statistics.steps,
      result.statistics.step_cuts);
  EXPECT_GT(most_active, 10);  // the turns land on each other
  EXPECT_LT(deepest, 0.2 * kRadius);
  EXPECT_GT(lowest, kRadius - 0.1 * kRadius);   // on the plane, not through it
  EXPECT_LT(final_kinetic, 0.7 * max_kinetic);  // settling, not gaining energy
}

// The coiled rope's landing with the contact couplings pruned hard (dropped 5 steps after their
// pair was last coupled) and kept for good, both with full Newton: the patterns differ, the
// equations and the iteration matrices do not (a pair gets its coupling blocks only while it
// touches or nearly touches at the step start, whatever else the pattern holds),
// so the positions agree to rounding, and the pruned pattern changes more often. (With the
// adaptive Jacobian, a rebuild also forces a fresh Jacobian; the converged steps then differ
// within the Newton tolerance, which the piling turns, with friction, amplify: 0.4 mm at 0.06 s.)
TEST(SelfContact, PruningTheContactCouplingsLeavesTheTrajectory) {
  const Model model = MakeCoiledRope();
  DynamicSettings pruned;
  pruned.time_step = 2e-4;
  pruned.end_time = 0.06;
  pruned.jacobian_update = JacobianUpdate::kEveryIteration;
  pruned.contact_couplings = {.near_factor = 1.0, .keep_updates = 5, .max_stale_fraction = 0.0};
  DynamicSettings kept = pruned;
  kept.contact_couplings = {.near_factor = 1.0, .keep_updates = -1};
  State pruned_state = MakeInitialState(model), kept_state = pruned_state;
  const auto ignore = [](const State&, const EnergyAccount&) {};
  const SolveResult a = SolveDynamic(model, pruned, 0.0, ignore, &pruned_state);
  const SolveResult b = SolveDynamic(model, kept, 0.0, ignore, &kept_state);
  ASSERT_TRUE(a.completed) << a.message;
  ASSERT_TRUE(b.completed) << b.message;
  double difference = 0.0, fall = 0.0;
  for (const PointMass& knot : model.point_masses()) {
    const Index z = knot.dof + 2;
    difference = std::max(difference,
                          (pruned_state.q.segment<3>(knot.dof) - kept_state.q.segment<3>(knot.dof))
                              .lpNorm<Eigen::Infinity>());
    fall = std::max(fall, MakeInitialState(model).q[z] - pruned_state.q[z]);
  }
  std::printf(
      "coiled rope, pruned / kept couplings: %ld / %ld pattern rebuilds, %ld / %ld steps, %ld / "
      "%ld Newton iterations; knots fell up to %.2e m, largest knot difference %.2e m\n",
      a.statistics.pattern_rebuilds, b.statistics.pattern_rebuilds, a.statistics.steps,
      b.statistics.steps, a.statistics.newton_iterations, b.statistics.newton_iterations, fall,
      difference);
  EXPECT_GT(fall, 0.005);       // it has landed
  EXPECT_LT(difference, 1e-9);  // m
  EXPECT_GT(a.statistics.pattern_rebuilds, b.statistics.pattern_rebuilds);
}

}  // namespace
}  // namespace ancfnet
