// StopIfInterrupted: what the time loop and the static solver do after each accepted step. With
// no request nothing happens; with one, a state not yet written goes to the outputs (so that they
// end at the state reached) and the result says interrupted, with the signal and the time.

#include <gtest/gtest.h>

#include <csignal>

#include "ancfnet/common/interrupt.hpp"
#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {
namespace {

TEST(StopIfInterrupted, WritesAStateBetweenOutputTimesAndSaysWhy) {
  State state;
  state.t = 0.2345;
  int outputs = 0;
  const OutputCallback count = [&](const State&, const EnergyAccount&) { ++outputs; };
  SolveResult result;
  EXPECT_FALSE(StopIfInterrupted(count, state, {}, /*written=*/false, &result));
  EXPECT_EQ(outputs, 0);
  EXPECT_TRUE(result.completed);

  RequestInterrupt(SIGINT);
  EXPECT_TRUE(StopIfInterrupted(count, state, {}, /*written=*/false, &result));
  EXPECT_EQ(outputs, 1);
  EXPECT_TRUE(StopIfInterrupted(count, state, {}, /*written=*/true, &result));
  EXPECT_EQ(outputs, 1);
  ClearInterrupt();
  EXPECT_EQ(InterruptRequested(), 0);
  EXPECT_FALSE(result.completed);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(result.message, "interrupted by SIGINT (2) at t = 0.2345");
}

}  // namespace
}  // namespace ancfnet
