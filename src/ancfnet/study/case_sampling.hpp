#pragma once
/// @file The parameter values of a study's cases: a full grid, or samples of each parameter's
/// distribution drawn at random or by Latin hypercube sampling, from a fixed seed. The draws
/// use only std::mt19937_64, whose sequence the C++ standard fixes, and arithmetic of our own,
/// so that a seed gives the same cases with every compiler and library.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ancfnet {

/// The values of case i are row i: one value per parameter, in the study's order.
using CaseTable = std::vector<std::vector<double>>;

/// Every combination of `values` (one list per parameter): the first parameter varies slowest,
/// the last fastest, as nested loops in the order the parameters are listed. ∏ sizes rows.
CaseTable MakeGridCases(const std::vector<std::vector<double>>& values);

/// `cases` points of the unit cube (0, 1)^dimensions, independent and uniform.
CaseTable DrawRandomUnitCases(std::size_t cases, std::size_t dimensions, std::uint64_t seed);

/// `cases` points of (0, 1)^dimensions by Latin hypercube sampling (McKay, Beckman & Conover
/// 1979): in each dimension the interval is cut into `cases` equal strata, and each stratum holds
/// exactly one point, at a uniform position within it; the strata are paired at random.
CaseTable DrawLatinHypercubeUnitCases(std::size_t cases, std::size_t dimensions,
                                      std::uint64_t seed);

/// The standard normal quantile Φ⁻¹(u) for u in (0, 1).
double StandardNormalQuantile(double u);

}  // namespace ancfnet
