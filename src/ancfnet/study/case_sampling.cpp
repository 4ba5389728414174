#include "ancfnet/study/case_sampling.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <random>
#include <utility>

namespace ancfnet {
namespace {

// A uniform number in (0, 1) from the top 53 bits of one draw: never 0 nor 1, so that a normal
// quantile of it is finite.
double OpenUnit(std::mt19937_64& generator) {
  return (static_cast<double>(generator() >> 11) + 0.5) * 0x1p-53;
}

// A uniform integer in [0, n) (n ≥ 1), from the top bits of one draw.
std::size_t Below(std::size_t n, std::mt19937_64& generator) {
  return static_cast<std::size_t>(OpenUnit(generator) * static_cast<double>(n));
}

}  // namespace

CaseTable MakeGridCases(const std::vector<std::vector<double>>& values) {
  CaseTable cases(1);
  for (const std::vector<double>& axis : values) {
    CaseTable extended;
    extended.reserve(cases.size() * axis.size());
    for (const std::vector<double>& prefix : cases)
      for (const double value : axis) {
        extended.push_back(prefix);
        extended.back().push_back(value);
      }
    cases = std::move(extended);
  }
  return cases;
}

CaseTable DrawRandomUnitCases(std::size_t cases, std::size_t dimensions, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  CaseTable table(cases, std::vector<double>(dimensions));
  for (std::vector<double>& row : table)
    for (double& u : row) u = OpenUnit(generator);
  return table;
}

CaseTable DrawLatinHypercubeUnitCases(std::size_t cases, std::size_t dimensions,
                                      std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  CaseTable table(cases, std::vector<double>(dimensions));
  std::vector<std::size_t> strata(cases);
  for (std::size_t d = 0; d < dimensions; ++d) {
    for (std::size_t i = 0; i < cases; ++i) strata[i] = i;
    for (std::size_t i = cases; i > 1; --i)  // Fisher–Yates
      std::swap(strata[i - 1], strata[Below(i, generator)]);
    // Below 1 even where the division rounds up (a normal quantile of 1 is infinite).
    for (std::size_t i = 0; i < cases; ++i)
      table[i][d] = std::min(
          (static_cast<double>(strata[i]) + OpenUnit(generator)) / static_cast<double>(cases),
          std::nextafter(1.0, 0.0));
  }
  return table;
}

double StandardNormalQuantile(double u) {
  return boost::math::quantile(boost::math::normal_distribution<double>(), u);
}

}  // namespace ancfnet
