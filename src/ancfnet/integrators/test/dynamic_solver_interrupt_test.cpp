// The time loop stops cleanly on an interrupt request (common/interrupt.hpp, what SIGINT and
// SIGTERM set in the CLI): it finishes the step in progress, writes the state reached, and
// reports interrupted, not completed (a state between output times: solvers/test/
// stop_if_interrupted_test.cpp).

#include <gtest/gtest.h>

#include <csignal>
#include <vector>

#include "ancfnet/common/interrupt.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// A point mass on a linear spring to a fixed anchor (ω = 20 rad/s).
Model MakeOscillator() {
  ModelBuilder builder;
  builder.AddPointMass("anchor", 1.0, Vector3d::Zero());
  builder.FixPointMass("anchor");
  builder.AddPointMass("mass", 2.0, Vector3d(1.1, 0.0, 0.0));
  builder.AddSpringDamper("spring", {"anchor"}, {"mass"}, MakeLinearLaw(800.0), 1.0);
  return builder.Build();
}

TEST(DynamicSolverInterrupt, StopsAtTheStepWhereTheRequestArrived) {
  const Model model = MakeOscillator();
  DynamicSettings settings;
  settings.time_step = 1e-3;
  settings.end_time = 1.0;
  State state = MakeInitialState(model);
  std::vector<double> output_times;
  // The request arrives while the output at t = 0.2 s is written.
  const SolveResult result = SolveDynamic(
      model, settings, /*output_interval=*/0.1,
      [&](const State& s, const EnergyAccount&) {
        output_times.push_back(s.t);
        if (s.t > 0.15) RequestInterrupt(SIGTERM);
      },
      &state);
  ClearInterrupt();
  EXPECT_FALSE(result.completed);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(result.message, "interrupted by SIGTERM (15) at t = 0.2");
  ASSERT_EQ(output_times.size(), 3u);  // 0, 0.1 and 0.2, not written twice
  EXPECT_EQ(state.t, output_times.back());
  EXPECT_NEAR(state.t, 0.2, 1e-12);
  EXPECT_EQ(result.statistics.steps, 200);
}

TEST(DynamicSolverInterrupt, NoRequestNoStop) {
  const Model model = MakeOscillator();
  DynamicSettings settings;
  settings.time_step = 1e-2;
  settings.end_time = 0.5;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.1, [](const State&, const EnergyAccount&) {}, &state);
  EXPECT_TRUE(result.completed);
  EXPECT_FALSE(result.interrupted);
  EXPECT_DOUBLE_EQ(state.t, 0.5);
}

}  // namespace
}  // namespace ancfnet
