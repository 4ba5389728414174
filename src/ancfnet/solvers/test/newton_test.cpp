// NewtonSolver on hand-made two-unknown problems: quadratic convergence to a known root, the
// line search that rescues a start from which plain Newton diverges, and the failures it reports
// (a singular iteration matrix, no convergence within the iteration limit).

#include "ancfnet/solvers/newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace ancfnet {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;

// R(x) = 0 with R and ∂R/∂x given as functions; converged when |Δx|∞ ≤ 10⁻¹⁰. Records the
// iterate after every full Newton increment.
class TwoUnknownProblem {
 public:
  using Residual = std::function<Vector2d(const Vector2d&)>;
  using Jacobian = std::function<Matrix2d(const Vector2d&)>;

  TwoUnknownProblem(Residual residual, Jacobian jacobian, const Vector2d& initial_guess)
      : residual_(std::move(residual)),
        jacobian_(std::move(jacobian)),
        initial_guess_(initial_guess),
        x_(initial_guess) {}

  Index size() const { return 2; }
  void Reset() { x_ = initial_guess_; }
  void CalcResidual(VectorXd* r) { *r = residual_(x_); }
  const SparseMatrixd& CalcIterationMatrix() {
    const Matrix2d j = jacobian_(x_);
    // Every entry stored, zero or not: the pattern the solver analysed does not change.
    std::vector<Eigen::Triplet<double>> entries;
    for (int row = 0; row < 2; ++row)
      for (int col = 0; col < 2; ++col) entries.emplace_back(row, col, j(row, col));
    matrix_.resize(2, 2);
    matrix_.setFromTriplets(entries.begin(), entries.end());
    return matrix_;
  }
  void ApplyIncrement(const VectorXd& dx, double scale) {
    x_ += scale * dx;
    if (scale == 1.0) iterates_.push_back(x_);
  }
  double IncrementNorm(const VectorXd& dx) const { return dx.cwiseAbs().maxCoeff() / 1e-10; }
  double IncrementEnergy(const VectorXd& dx, const VectorXd& r) const {
    return std::abs(dx.dot(r));
  }
  double ResidualWork(const VectorXd& r) const { return std::abs((x_ - initial_guess_).dot(r)); }
  double EnergyScale() const { return 1.0; }

  const Vector2d& x() const { return x_; }
  const std::vector<Vector2d>& iterates() const { return iterates_; }

 private:
  Residual residual_;
  Jacobian jacobian_;
  Vector2d initial_guess_;
  Vector2d x_;
  SparseMatrixd matrix_;
  std::vector<Vector2d> iterates_;
};

// R = (x₀² + x₁ − 3, x₀ + x₁² − 5), root (1, 2) with ∂R/∂x = [2 1; 1 4] there.
TwoUnknownProblem MakeQuadraticProblem(const Vector2d& initial_guess) {
  return TwoUnknownProblem(
      [](const Vector2d& x) {
        return Vector2d(x[0] * x[0] + x[1] - 3.0, x[0] + x[1] * x[1] - 5.0);
      },
      [](const Vector2d& x) {
        return Matrix2d{{2.0 * x[0], 1.0}, {1.0, 2.0 * x[1]}};
      },
      initial_guess);
}

// R = (atan x₀, x₁ − 1), root (0, 1). Plain Newton on atan diverges from |x₀| > 1.39.
TwoUnknownProblem MakeArctangentProblem(const Vector2d& initial_guess) {
  return TwoUnknownProblem([](const Vector2d& x) { return Vector2d(std::atan(x[0]), x[1] - 1.0); },
                           [](const Vector2d& x) {
                             return Matrix2d{{1.0 / (1.0 + x[0] * x[0]), 0.0}, {0.0, 1.0}};
                           },
                           initial_guess);
}

NewtonSolver MakeFullNewton(LineSearchMode line_search, int max_iterations = 12) {
  return NewtonSolver({.max_iterations = max_iterations, .line_search = line_search},
                      JacobianUpdate::kEveryIteration);
}

TEST(NewtonTest, ConvergesQuadraticallyToTheRoot) {
  const Vector2d root(1.0, 2.0);
  TwoUnknownProblem problem = MakeQuadraticProblem(Vector2d(2.0, 3.0));
  NewtonSolver newton = MakeFullNewton(LineSearchMode::kNever);
  const NewtonResult result = newton.Solve(problem);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_LT((problem.x() - root).norm(), 1e-15);
  EXPECT_EQ(result.jacobian_updates, result.iterations);
  EXPECT_LE(result.iterations, 6);
  // For a quadratic R the error obeys e_{k+1} = J(x_k)⁻¹ (e₀², e₁²) exactly, so
  // |e_{k+1}| ≤ |J⁻¹| |e_k|² with |J⁻¹| ≈ 0.65 near the root; a linearly converging method would
  // break this bound within two iterations.
  const std::vector<Vector2d>& iterates = problem.iterates();
  int quadratic_steps = 0;
  for (std::size_t k = 0; k + 1 < iterates.size(); ++k) {
    const double e = (iterates[k] - root).norm();
    const double e_next = (iterates[k + 1] - root).norm();
    if (e > 0.1 || e_next < 1e-15) continue;
    EXPECT_LT(e_next, 0.7 * e * e) << "iteration " << k + 1;
    ++quadratic_steps;
  }
  EXPECT_GE(quadratic_steps, 2);
}

TEST(NewtonTest, LineSearchRescuesAStartFromWhichPlainNewtonDiverges) {
  TwoUnknownProblem plain = MakeArctangentProblem(Vector2d(2.0, 0.0));
  NewtonSolver plain_newton = MakeFullNewton(LineSearchMode::kNever, /*max_iterations=*/8);
  const NewtonResult diverged = plain_newton.Solve(plain);
  EXPECT_FALSE(diverged.converged);
  EXPECT_EQ(diverged.failure, "no convergence in 8 iterations");
  EXPECT_GT(std::abs(plain.x()[0]), 1e20);  // |x₀| roughly squares every iteration

  TwoUnknownProblem damped = MakeArctangentProblem(Vector2d(2.0, 0.0));
  NewtonSolver damped_newton = MakeFullNewton(LineSearchMode::kAlways);
  const NewtonResult result = damped_newton.Solve(damped);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_LT((damped.x() - Vector2d(0.0, 1.0)).norm(), 1e-12);
}

TEST(NewtonTest, AutoModeRetriesAFailedPlainAttemptWithDampedSteps) {
  // The plain attempt diverges as above (8 iterations), then the damped retry from the initial
  // guess converges; the result counts both attempts.
  TwoUnknownProblem problem = MakeArctangentProblem(Vector2d(2.0, 0.0));
  NewtonSolver newton = MakeFullNewton(LineSearchMode::kAuto, /*max_iterations=*/8);
  const NewtonResult result = newton.Solve(problem);
  ASSERT_TRUE(result.converged) << result.failure;
  EXPECT_LT((problem.x() - Vector2d(0.0, 1.0)).norm(), 1e-12);
  EXPECT_GT(result.iterations, 8);
  EXPECT_EQ(result.jacobian_updates, result.iterations);
}

TEST(NewtonTest, ReportsASingularIterationMatrix) {
  // R = (x₀ + x₁ − 1, 2 x₀ + 2 x₁ − 3): parallel lines, no root, ∂R/∂x singular everywhere.
  TwoUnknownProblem problem(
      [](const Vector2d& x) { return Vector2d(x[0] + x[1] - 1.0, 2.0 * x[0] + 2.0 * x[1] - 3.0); },
      [](const Vector2d&) {
        return Matrix2d{{1.0, 1.0}, {2.0, 2.0}};
      },
      Vector2d::Zero());
  NewtonSolver newton = MakeFullNewton(LineSearchMode::kNever);
  const NewtonResult result = newton.Solve(problem);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.failure, "singular iteration matrix");
  EXPECT_EQ(result.iterations, 1);
  EXPECT_TRUE(problem.iterates().empty());
}

}  // namespace
}  // namespace ancfnet
