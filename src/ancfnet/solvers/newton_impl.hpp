#pragma once
/// @file Template definitions of NewtonSolver (included by newton.hpp).

#include <cmath>

namespace ancfnet {

// Smallest damping factor of a Newton step before the iterations are declared stuck.
inline constexpr double kMinDamping = 1.0 / 256.0;
// Iterations of a converged solve above which the next solve starts with a fresh Jacobian.
inline constexpr int kSlowConvergenceIterations = 4;
// An old Jacobian is renewed once an iteration shrinks the increment by less than this factor.
inline constexpr double kStaleContraction = 0.5;
// A weighted increment norm this small is rounding (Δq ≈ 10⁻¹⁴ |q| with rtol = 10⁻⁶): no
// correction could do better, whatever energy test is asked for.
inline constexpr double kRoundingNorm = 1e-8;

inline NewtonSolver::NewtonSolver(const NewtonSettings& settings, JacobianUpdate update,
                                  LinearSolverType linear_solver)
    : settings_(settings), update_(update), linear_solver_(linear_solver) {}

inline void NewtonSolver::SaveCheckpoint(ArchiveWriter* out) const {
  out->Write(has_factorization_);
  out->Write(jacobian_fresh_);
  out->Write(last_iterations_);
  linear_solver_.SaveCheckpoint(out);
}

inline void NewtonSolver::LoadCheckpoint(ArchiveReader* in) {
  has_factorization_ = in->Read<bool>();
  jacobian_fresh_ = in->Read<bool>();
  last_iterations_ = in->Read<int>();
  linear_solver_.LoadCheckpoint(in);
}

template <class Problem>
NewtonResult NewtonSolver::Solve(Problem& problem) {
  const bool damped = settings_.line_search == LineSearchMode::kAlways;
  NewtonResult result = Iterate(problem, /*force_refresh=*/false, damped);
  // Each retry starts again from the initial guess; the counts add up over the attempts, and a
  // failed damped retry reports why the plain attempt failed too.
  auto retry = [&](bool retry_damped) {
    problem.Reset();
    const NewtonResult again = Iterate(problem, /*force_refresh=*/true, retry_damped);
    const std::string failure =
        again.converged || retry_damped == damped
            ? again.failure
            : result.failure + "; retried with damped steps: " + again.failure;
    result = {again.converged, result.iterations + again.iterations,
              result.jacobian_updates + again.jacobian_updates, failure};
  };
  // A stale Jacobian may be what failed.
  if (!result.converged && update_ != JacobianUpdate::kEveryIteration) retry(damped);
  // Plain Newton is fastest when it converges; damping is the fallback before a cut, for
  // residuals whose curvature outruns the full step (e.g. regularised friction over a small
  // sliding speed at a small time step).
  if (!result.converged && settings_.line_search == LineSearchMode::kAuto) retry(true);
  return result;
}

template <class Problem>
bool NewtonSolver::Refresh(Problem& problem, NewtonResult* result) {
  ++result->jacobian_updates;
  has_factorization_ = linear_solver_.Factorize(problem.CalcIterationMatrix());
  jacobian_fresh_ = has_factorization_;
  if (!has_factorization_) result->failure = "singular iteration matrix";
  return has_factorization_;
}

template <class Problem>
double NewtonSolver::LineSearch(Problem& problem, double increment_norm) {
  // Damped Newton with the natural monotonicity test of Deuflhard (2004, sec. 3.3, NLEQ-ERR):
  // accept the step length α when the simplified correction d̄ = −J⁻¹ R(x + α d), computed with
  // the current factorisation, satisfies ‖d̄‖ ≤ (1 − α/4) ‖d‖. Unlike a test on ‖R‖ it is affine
  // invariant, so the very different stiffness of stretching and bending does not reject good
  // steps. Both corrections are measured in the plain Euclidean norm: the weights of the
  // convergence norm differ by orders of magnitude between coordinates near zero and the others,
  // which would break the invariance. The increment is already applied with α = 1.
  double alpha = 1.0;
  while (alpha >= kMinDamping) {
    problem.CalcResidual(&residual_);
    if (residual_.allFinite()) {
      linear_solver_.Solve(residual_, &simplified_);
      const double norm = simplified_.norm();
      if (std::isfinite(norm) && norm <= (1.0 - 0.25 * alpha) * increment_norm) break;
    }
    problem.ApplyIncrement(increment_, -0.5 * alpha);
    alpha *= 0.5;
  }
  return alpha;
}

template <class Problem>
NewtonResult NewtonSolver::Iterate(Problem& problem, bool force_refresh, bool damped) {
  NewtonResult result;
  const bool every_iteration = force_refresh || update_ == JacobianUpdate::kEveryIteration;
  // Adaptive reuse: an old Jacobian that needed many iterations last time is renewed at once.
  const bool slow_last_time = last_iterations_ > kSlowConvergenceIterations;
  const bool refresh_first =
      every_iteration || update_ == JacobianUpdate::kEveryStep || slow_last_time;
  double previous_norm = 0.0;
  // The last correction was a full step that passed the increment test: the residual at the
  // corrected iterate decides.
  bool increment_converged = false;
  bool at_rounding = false;  // and it was at the level of rounding
  for (int it = 0;; ++it) {
    problem.CalcResidual(&residual_);
    if (!residual_.allFinite()) {
      result.failure = "non-finite residual";
      return result;
    }
    // The work of the residual force over the step is the energy the step would wrongly create
    // or destroy if accepted now (for the energy-consistent midpoint rule exactly its balance
    // error): it must be a small fraction of the energy the step exchanges. A correction at the
    // level of rounding is accepted whatever the residual: no correction could do better.
    if (increment_converged &&
        (at_rounding ||
         problem.ResidualWork(residual_) <= settings_.energy_tolerance * problem.EnergyScale())) {
      result.converged = true;
      last_iterations_ = result.iterations;
      return result;
    }
    if (it == settings_.max_iterations) break;
    result.iterations = it + 1;
    const bool refresh = !has_factorization_ || every_iteration || (it == 0 && refresh_first);
    if (refresh && !Refresh(problem, &result)) return result;
    linear_solver_.Solve(residual_, &increment_);
    increment_ = -increment_;
    double norm = problem.IncrementNorm(increment_);
    if (!std::isfinite(norm)) {
      result.failure = "non-finite Newton increment";
      return result;
    }
    // An old Jacobian that no longer contracts (or diverges) is refreshed and the iteration
    // redone. With a fresh Jacobian, Newton far from the solution need not be monotone: only the
    // iteration limit and non-finite values stop it.
    if (it > 0 && !jacobian_fresh_ && norm > kStaleContraction * previous_norm) {
      if (!Refresh(problem, &result)) return result;
      linear_solver_.Solve(residual_, &increment_);
      increment_ = -increment_;
      norm = problem.IncrementNorm(increment_);
    }
    // |Δxᵀ R|: twice the strain energy left in the stiffest modes near the root, which a small
    // increment of a stiff system still leaves large.
    const double correction_energy = problem.IncrementEnergy(increment_, residual_);
    problem.ApplyIncrement(increment_, 1.0);
    jacobian_fresh_ = false;
    const double step = damped ? LineSearch(problem, increment_.norm()) : 1.0;
    if (step < kMinDamping) {
      result.failure = "damped Newton step too small (no descent)";
      return result;
    }
    previous_norm = norm;
    // Converged only on a full step: a small damped step says nothing about the distance left.
    // The energy test is taken with the scale at the corrected iterate.
    at_rounding = norm <= kRoundingNorm;
    increment_converged =
        step == 1.0 && norm <= 1.0 &&
        (at_rounding || correction_energy <= settings_.energy_tolerance * problem.EnergyScale());
  }
  result.failure = "no convergence in " + std::to_string(settings_.max_iterations) + " iterations";
  return result;
}

}  // namespace ancfnet
