// The cases of a study: grid order and count, Latin hypercube strata, seeded draws.
#include "ancfnet/study/case_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace ancfnet {
namespace {

TEST(StudySampling, GridHasEveryCombinationFirstParameterSlowest) {
  const CaseTable cases = MakeGridCases({{1, 2}, {10, 20, 30}, {100}});
  ASSERT_EQ(cases.size(), 6u);
  const CaseTable expected = {{1, 10, 100}, {1, 20, 100}, {1, 30, 100},
                              {2, 10, 100}, {2, 20, 100}, {2, 30, 100}};
  EXPECT_EQ(cases, expected);
}

TEST(StudySampling, LatinHypercubeHitsEachStratumOncePerDimension) {
  for (const std::size_t n : {1u, 2u, 7u, 50u}) {
    const CaseTable cases = DrawLatinHypercubeUnitCases(n, 3, 42);
    ASSERT_EQ(cases.size(), n);
    for (std::size_t d = 0; d < 3; ++d) {
      std::set<std::size_t> strata;
      for (const std::vector<double>& row : cases) {
        ASSERT_GT(row[d], 0.0);
        ASSERT_LT(row[d], 1.0);
        strata.insert(static_cast<std::size_t>(std::floor(row[d] * static_cast<double>(n))));
      }
      EXPECT_EQ(strata.size(), n) << "n = " << n << ", dimension " << d;
    }
  }
}

TEST(StudySampling, DrawsRepeatWithTheSameSeedAndDifferWithAnother) {
  EXPECT_EQ(DrawRandomUnitCases(20, 2, 7), DrawRandomUnitCases(20, 2, 7));
  EXPECT_NE(DrawRandomUnitCases(20, 2, 7), DrawRandomUnitCases(20, 2, 8));
  EXPECT_EQ(DrawLatinHypercubeUnitCases(20, 2, 7), DrawLatinHypercubeUnitCases(20, 2, 7));
  EXPECT_NE(DrawLatinHypercubeUnitCases(20, 2, 7), DrawLatinHypercubeUnitCases(20, 2, 8));
  // The first draw of std::mt19937_64 with seed 7 is fixed by the standard, so is this value.
  const double first = DrawRandomUnitCases(1, 1, 7)[0][0];
  EXPECT_EQ(first, DrawRandomUnitCases(3, 1, 7)[0][0]);
  EXPECT_GT(first, 0.0);
  EXPECT_LT(first, 1.0);
}

TEST(StudySampling, RandomDrawsAreUniformOnAverage) {
  const CaseTable cases = DrawRandomUnitCases(4000, 1, 3);
  double sum = 0.0;
  for (const std::vector<double>& row : cases) sum += row[0];
  EXPECT_NEAR(sum / 4000.0, 0.5, 0.02);  // standard error 0.0046
}

TEST(StudySampling, NormalQuantileHasKnownValues) {
  EXPECT_NEAR(StandardNormalQuantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(StandardNormalQuantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(StandardNormalQuantile(0.025), -1.959963984540054, 1e-12);
}

}  // namespace
}  // namespace ancfnet
