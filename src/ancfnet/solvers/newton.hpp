#pragma once
/// @file Newton iterations with Jacobian reuse, optional backtracking line search and a
/// divergence check. The problem (a time step or a load increment) supplies the residual, the
/// iteration matrix and how an increment of the unknown changes its state.

#include <string>

#include "ancfnet/common/types.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {

/// What Newton needs of a problem R(x) = 0 whose unknown x lives inside the problem:
///   Index size() const;
///   void Reset();                                  back to the initial guess
///   void CalcResidual(VectorXd* r);                R at the current iterate
///   const SparseMatrixd& CalcIterationMatrix();    ∂R/∂x at the current iterate
///   void ApplyIncrement(const VectorXd& dx, double scale);   x += scale · dx
///   double IncrementNorm(const VectorXd& dx) const;   weighted RMS norm (≤ 1: converged)
///   double IncrementEnergy(const VectorXd& dx, const VectorXd& r) const;  |Δqᵀ R| (J) of the
///                                                  position increment Δq that dx gives
///   double ResidualWork(const VectorXd& r) const;   |Δqᵀ R| (J): the work of the residual's
///                                                  force rows R over the displacement Δq of
///                                                  the whole step (or load increment) so far
///   double EnergyScale() const;                    energy the step exchanges (J), ≥ 0
struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  int jacobian_updates = 0;
  std::string failure;  ///< why it did not converge
};

class NewtonSolver {
 public:
  NewtonSolver(const NewtonSettings& settings, JacobianUpdate update,
               LinearSolverType linear_solver = LinearSolverType::kKlu);

  /// Iterates from the problem's initial guess. With a stale Jacobian that fails, retries once
  /// from the initial guess with a fresh Jacobian at every iteration; with
  /// LineSearchMode::kAuto, an attempt with plain steps that fails is retried once more from the
  /// initial guess with damped steps and a fresh Jacobian at every iteration.
  template <class Problem>
  NewtonResult Solve(Problem& problem);

  /// Marks the stored factorisation as stale (e.g. after a change of time step).
  void InvalidateJacobian() {
    jacobian_fresh_ = false;
    has_factorization_ = false;
  }
  /// The iteration matrix has a new pattern (contact couplings were added).
  void InvalidatePattern() {
    InvalidateJacobian();
    linear_solver_.ForgetPattern();
  }
  /// Writes the state of the Jacobian reuse (whether a factorisation is held and fresh, the
  /// iterations of the last solve) and the linear solver's (SparseLinearSolver::SaveCheckpoint):
  /// all that the next solves depend on besides the problem.
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Recreates what SaveCheckpoint wrote.
  void LoadCheckpoint(ArchiveReader* in);

 private:
  template <class Problem>
  NewtonResult Iterate(Problem& problem, bool force_refresh, bool damped);
  template <class Problem>
  bool Refresh(Problem& problem, NewtonResult* result);
  template <class Problem>
  double LineSearch(Problem& problem, double increment_norm);

  NewtonSettings settings_;
  JacobianUpdate update_;
  SparseLinearSolver linear_solver_;
  bool has_factorization_ = false;
  bool jacobian_fresh_ = false;  // factorised at the current iterate
  int last_iterations_ = 0;      // iterations of the last converged solve
  VectorXd residual_;
  VectorXd increment_;
  VectorXd simplified_;
};

}  // namespace ancfnet

#include "ancfnet/solvers/newton_impl.hpp"
