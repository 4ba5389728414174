// Failure of connections and threads: a link breaks when its tension reaches its breaking force,
// at the time the analytical motion predicts, releasing its stored energy; a thread of a
// compliant net that reaches its breaking tension comes off both knots; momentum is conserved
// through a break, and what cannot come off is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ancfnet/analysis/momentum.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

// The implicit midpoint rule, h = 1e-5 s, Newton converged far below the effects measured.
DynamicSettings TightMidpoint(double end_time) {
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 1e-5;
  settings.end_time = end_time;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  return settings;
}

// A mass m on a linear spring k (L₀ = 0.5 m) from a fixed anchor, at rest length and moving
// outward at v₀: e(t) = (v₀/ω) sin ωt, T = k e, ω = √(k/m). The link breaks when T = F_b, at
// t_b = asin(F_b ω/(k v₀))/ω, and the mass then flies on at v₀ cos(ω t_b).
TEST(Failure, LinkBreaksAtTheAnalyticalTimeAndReleasesItsEnergy) {
  const double m = 0.1, k = 100.0, v0 = 2.0, breaking = 5.0;
  ModelBuilder builder;
  builder.AddPointMass("anchor", 1.0, Vector3d::Zero());
  builder.FixPointMass("anchor");
  builder.AddPointMass("mass", m, Vector3d(0.5, 0.0, 0.0), Vector3d(v0, 0.0, 0.0));
  builder.AddSpringDamper("link", {"anchor"}, {"mass"}, MakeLinearLaw(k), 0.5, breaking);
  const Model model = builder.Build();
  const DynamicSettings settings = TightMidpoint(0.05);
  State state = MakeInitialState(model);
  double kinetic0 = -1.0, worst_balance = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State&, const EnergyAccount& e) {
        if (kinetic0 < 0.0) kinetic0 = e.kinetic;
        worst_balance = std::max(worst_balance, std::abs(e.Balance() - kinetic0));
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  ASSERT_EQ(result.failures.size(), 1u);
  const double omega = std::sqrt(k / m);
  const double t_break = std::asin(breaking * omega / (k * v0)) / omega;  // 0.02886 s
  EXPECT_EQ(result.failures[0].what, "link");
  // Detected at the end of the step in which T crosses F_b.
  EXPECT_GE(result.failures[0].time, t_break - 1e-12);
  EXPECT_LE(result.failures[0].time, t_break + settings.time_step);
  EXPECT_GE(result.failures[0].tension, breaking);
  EXPECT_LT(result.failures[0].tension, breaking * 1.001);
  EXPECT_EQ(state.link_broken[0], 1);
  // Free flight afterwards at the speed the analytical motion had at t_b (within the one step).
  const double v_after = v0 * std::cos(omega * t_break);
  EXPECT_NEAR(state.v[model.point_masses()[1].dof], v_after, 2e-3 * v0);
  EXPECT_NEAR(state.v[model.point_masses()[1].dof + 1], 0.0, 1e-12);
  // Kinetic + spring energy + released energy stays the initial kinetic energy.
  EXPECT_LT(worst_balance, 1e-6 * kinetic0);
}

// Two knots (20 g) flying apart at ±3 m/s along x, held by one 0.5 m rope thread (EA = 2356 N)
// joined to each knot by a stiff link: unbroken, the tension would peak at some 40 N (½ k x² = T₀,
// k ≈ EA/L in series with the links, a rough estimate); at its breaking force it fails, and
// both links go.
struct ThreadRun {
  SolveResult result;
  Vector3d p0 = Vector3d::Zero(), p_end = Vector3d::Zero();
  State state;
};

ThreadRun PullThread(double thread_breaking, double link_breaking) {
  NetSpec spec;
  spec.name = "pair";
  spec.topology = MakeGraphNet({Vector3d(-0.25, 0, 0), Vector3d(0.25, 0, 0)}, {{0, 1}});
  spec.thread =
      MakeCableProperties({.youngs_modulus = 3e9, .density = 1140}, MakeCircleSection(0.001));
  spec.thread.tension_only = true;
  spec.thread.rope_smoothing_strain = 1e-4;
  spec.elements_per_thread = 2;
  spec.knot_model = KnotModel::kCompliant;
  spec.knot_mass = 0.02;
  spec.link_law = WithConstantDamping(MakeLinearLaw(1e6), 0.1);
  spec.knot_masses = {{0, 1e-9, Vector3d(-3, 0, 0)}, {1, 1e-9, Vector3d(3, 0, 0)}};
  spec.thread_breaking_force = thread_breaking;
  spec.link_breaking_force = link_breaking;
  ModelBuilder builder;
  AddNet(builder, spec);
  const Model model = builder.Build();
  const Workspace ws(model);
  const DynamicSettings settings = TightMidpoint(0.01);
  ThreadRun run;
  run.state = MakeInitialState(model);
  run.p0 = CalcLinearMomentum(model, ws, run.state.v);
  run.result = SolveDynamic(
      model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &run.state);
  run.p_end = CalcLinearMomentum(model, ws, run.state.v);
  return run;
}

TEST(Failure, ThreadComesOffBothKnotsAtItsBreakingTension) {
  const double breaking = 30.0;  // N
  const ThreadRun run = PullThread(breaking, std::numeric_limits<double>::infinity());
  ASSERT_TRUE(run.result.completed) << run.result.message;
  ASSERT_EQ(run.result.failures.size(), 1u);
  EXPECT_EQ(run.result.failures[0].what, "pair.t0");
  EXPECT_GE(run.result.failures[0].tension, breaking);
  EXPECT_LT(run.result.failures[0].tension, 1.05 * breaking);  // within one step's rise
  EXPECT_EQ(run.state.link_broken, (std::vector<char>{1, 1}));
  // The break removes internal forces only: momentum stays (zero by symmetry, round-off).
  EXPECT_LT((run.p_end - run.p0).norm(), 1e-12);
}

TEST(Failure, WeakLinksFailBeforeTheThread) {
  const ThreadRun run = PullThread(1e4, 15.0);
  ASSERT_TRUE(run.result.completed) << run.result.message;
  ASSERT_GE(run.result.failures.size(), 1u);
  for (const FailureEvent& f : run.result.failures) {
    EXPECT_TRUE(f.what == "pair.t0.start" || f.what == "pair.t0.end") << f.what;
    EXPECT_GE(f.tension, 15.0);
  }
  EXPECT_EQ(run.state.link_broken, (std::vector<char>{1, 1}));
}

TEST(Failure, UnbreakableThreadsHold) {
  // Far above the peak tension: nothing fails (the same run with 30 N does).
  const ThreadRun run = PullThread(200.0, 200.0);
  ASSERT_TRUE(run.result.completed) << run.result.message;
  EXPECT_TRUE(run.result.failures.empty());
  EXPECT_EQ(run.state.link_broken, (std::vector<char>{0, 0}));
}

TEST(Failure, WhatCannotComeOffIsRefused) {
  NetSpec spec;
  spec.name = "ideal";
  spec.topology = MakeGraphNet({Vector3d(0, 0, 0), Vector3d(1, 0, 0)}, {{0, 1}});
  spec.thread =
      MakeCableProperties({.youngs_modulus = 3e9, .density = 1140}, MakeCircleSection(0.001));
  spec.thread_breaking_force = 100.0;
  ModelBuilder builder;
  EXPECT_THROW(AddNet(builder, spec), InputError);
  ModelBuilder links;
  links.AddPointMass("a", 1.0, Vector3d::Zero());
  links.AddPointMass("b", 1.0, Vector3d::UnitX());
  EXPECT_THROW(links.AddSpringDamper("l", {"a"}, {"b"}, MakeLinearLaw(1.0), 1.0, 0.0), InputError);
  EXPECT_THROW(links.AddSpringDamper("l", {"a"}, {"b"}, MakeLinearLaw(1.0), 1.0, std::nan("")),
               InputError);
}

}  // namespace
}  // namespace ancfnet
