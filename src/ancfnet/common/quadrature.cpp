#include "ancfnet/common/quadrature.hpp"

#include <Eigen/Eigenvalues>
#include <cassert>
#include <cmath>

#include "ancfnet/common/types.hpp"

namespace ancfnet {
namespace {

// Golub & Welsch (1969): the nodes are the eigenvalues of the symmetric tridiagonal Jacobi matrix
// of the Legendre recurrence, β_k = k / sqrt(4k² − 1); the weights are 2 v₀² on [−1, 1].
GaussRule MakeGaussRule(int n) {
  MatrixXd jacobi = MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) {
    const double beta = k / std::sqrt(4.0 * k * k - 1.0);
    jacobi(k, k - 1) = beta;
    jacobi(k - 1, k) = beta;
  }
  Eigen::SelfAdjointEigenSolver<MatrixXd> eig(jacobi);
  GaussRule rule;
  rule.size = n;
  for (int i = 0; i < n; ++i) {
    rule.points[i] = 0.5 * (eig.eigenvalues()(i) + 1.0);  // map [−1, 1] → [0, 1]
    const double v0 = eig.eigenvectors()(0, i);
    rule.weights[i] = v0 * v0;  // 2 v₀² on [−1, 1], halved by the map
  }
  return rule;
}

std::array<GaussRule, kMaxGaussPoints> MakeAllRules() {
  std::array<GaussRule, kMaxGaussPoints> rules;
  for (int n = 1; n <= kMaxGaussPoints; ++n) rules[n - 1] = MakeGaussRule(n);
  return rules;
}

}  // namespace

const GaussRule& GetGaussRule(int n) {
  assert(n >= 1 && n <= kMaxGaussPoints);
  static const std::array<GaussRule, kMaxGaussPoints> rules = MakeAllRules();
  return rules[n - 1];
}

double CalcGaussPointBasis(const GaussRule& rule, int i, double xi) {
  double basis = 1.0;
  for (int j = 0; j < rule.size; ++j)
    if (j != i) basis *= (xi - rule.points[j]) / (rule.points[i] - rule.points[j]);
  return basis;
}

}  // namespace ancfnet
