#pragma once
/// @file Sparse direct solver for the iteration matrix: the pattern is analysed once, the
/// numeric factorisation is redone when the Jacobian is refreshed.

#include <memory>

#include "ancfnet/common/binary_archive.hpp"
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
  /// Writes what the next factorisations depend on: for KLU the matrix whose factorisation set
  /// the pivot order that refactorisations reuse, and the matrix last factorised (pattern and
  /// values), so that LoadCheckpoint recreates the factorisation bit for bit.
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Recreates the state SaveCheckpoint wrote (analysis, pivot order, last factorisation).
  /// Throws InputError when the checkpoint's matrices cannot be factorised again.
  void LoadCheckpoint(ArchiveReader* in);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ancfnet
