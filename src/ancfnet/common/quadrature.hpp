#pragma once
/// @file Gauss–Legendre quadrature on the unit interval.

#include <array>

namespace ancfnet {

/// Largest number of Gauss points a rule may have.
inline constexpr int kMaxGaussPoints = 8;

/// Gauss–Legendre rule on [0, 1]: ∫₀¹ f(ξ) dξ ≈ Σ w_i f(ξ_i), exact for polynomials of degree
/// 2n − 1 (Abramowitz & Stegun 1964, 25.4.29).
struct GaussRule {
  int size = 0;
  std::array<double, kMaxGaussPoints> points{};
  std::array<double, kMaxGaussPoints> weights{};
};

/// Returns the n-point Gauss–Legendre rule on [0, 1], 1 ≤ n ≤ kMaxGaussPoints, computed by the
/// Golub–Welsch eigenvalue method (Golub & Welsch 1969). Results are cached; thread-safe.
const GaussRule& GetGaussRule(int n);

/// The Lagrange basis polynomial of Gauss point i of `rule` at ξ (extrapolating outside the
/// points): ℓᵢ(ξ) = ∏_{j≠i} (ξ − ξⱼ) / (ξᵢ − ξⱼ). Σᵢ fᵢ ℓᵢ(ξ) is the polynomial of degree n − 1
/// through values fᵢ at the points (the Gauss-point extrapolation of Hinton & Campbell 1974).
double CalcGaussPointBasis(const GaussRule& rule, int i, double xi);

}  // namespace ancfnet
