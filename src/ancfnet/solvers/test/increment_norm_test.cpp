// The weights and the weighted RMS norm of Newton's convergence test (solvers/solve_result.hpp).

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {
namespace {

TEST(IncrementNorm, WeightsFollowTheScaleOfEachUnknownsCoordinate) {
  // Coordinates 0..3 with scales (0.5, 0.5, 1, 1); unknowns are coordinates 1 and 2.
  const VectorXd scales = (VectorXd(4) << 0.5, 0.5, 1.0, 1.0).finished();
  const VectorXd weights = CalcIncrementWeights(scales, {1, 2}, 1e-6, 1e-8);
  ASSERT_EQ(weights.size(), 2);
  EXPECT_DOUBLE_EQ(weights[0], 1e-8 + 0.5e-6);
  EXPECT_DOUBLE_EQ(weights[1], 1e-8 + 1e-6);
}

TEST(IncrementNorm, IsTheRootMeanSquareOfTheScaledIncrements) {
  const VectorXd weights = (VectorXd(2) << 1e-6, 2e-6).finished();
  const VectorXd dx = (VectorXd(2) << 3e-6, -8e-6).finished();
  // √(((3)² + (4)²)/2) = 5/√2, times the scale 2.
  EXPECT_NEAR(WeightedRmsNorm(dx, weights, 2.0), 10.0 / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(WeightedRmsNorm(VectorXd(), VectorXd(), 1.0), 0.0);
}

}  // namespace
}  // namespace ancfnet
