#pragma once
/// @file Sparse direct solver for the iteration matrix: the pattern is analysed once, the
/// numeric factorisation is redone when the Jacobian is refreshed.

#include <memory>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

enum class LinearSolverType {
  kKlu,       ///< SuiteSparse KLU, pivot order reused by refactorisation; fast for banded systems
  kSparseLu,  ///< Eigen's supernodal SparseLU
};

class SparseLinearSolver {
 public:
  explicit SparseLinearSolver(LinearSolverType type = LinearSolverType::kKlu);
  ~SparseLinearSolver();
  SparseLinearSolver(SparseLinearSolver&&) noexcept;
  SparseLinearSolver& operator=(SparseLinearSolver&&) noexcept;

  /// Factorises `a` (analysing its pattern on the first call; the pattern must not change
  /// afterwards unless ForgetPattern is called). Returns false when the matrix is singular.
  bool Factorize(const SparseMatrixd& a);
  /// Drops the analysis and the factorisation: the next Factorize analyses a new pattern.
  void ForgetPattern();
  /// x = A⁻¹ b with the last factorisation.
  void Solve(const VectorXd& b, VectorXd* x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ancfnet
