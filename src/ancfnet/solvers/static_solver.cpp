#include "ancfnet/solvers/static_solver.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/solvers/newton.hpp"

namespace ancfnet {
namespace {

// One load increment as a Newton problem: R(q) = Q_int(q) − λ Q_ext(q) over the unknowns.
class LoadIncrement {
 public:
  LoadIncrement(const Model& model, const NewtonSettings& newton, Workspace& ws, State& state)
      : model_(model),
        newton_(newton),
        ws_(ws),
        state_(state),
        dofs_(DofMap::FreeCoordinates(model)),
        matrix_(model, dofs_),
        q_start_(state.q),
        residual_full_(state.q.size()) {}

  void Begin(double load_factor) {
    load_factor_ = load_factor;
    q_start_ = state_.q;
  }
  Index size() const { return dofs_.num_unknowns(); }
  void Reset() { state_.q = q_start_; }
  void CalcResidual(VectorXd* r) {
    CalcInternalForces(model_, state_.q, state_.v, ws_);
    CalcExternalForces(model_, state_.q, load_factor_, ws_);
    residual_full_ = ws_.internal_force - ws_.external_force;
    dofs_.Restrict(residual_full_, r);
  }
  const SparseMatrixd& CalcIterationMatrix() {
    AssembleIterationMatrix(model_, state_.q, state_.v, {.stiffness = 1.0}, load_factor_, ws_,
                            &matrix_);
    return matrix_.matrix();
  }
  void ApplyIncrement(const VectorXd& dx, double scale) { dofs_.AddExpanded(dx, scale, &state_.q); }
  double IncrementNorm(const VectorXd& dx) const {
    return WeightedRmsNorm(dx, state_.q, dofs_.coordinates(), 1.0, newton_.relative_tolerance,
                           newton_.absolute_tolerance);
  }
  double IncrementEnergy(const VectorXd& dx, const VectorXd& r) const {
    return std::abs(dx.dot(r));
  }
  // The work of the internal and applied forces over the increment so far (forces of the last
  // CalcResidual).
  double EnergyScale() const {
    return std::abs((state_.q - q_start_).dot(ws_.internal_force)) +
           std::abs((state_.q - q_start_).dot(ws_.external_force));
  }

 private:
  const Model& model_;
  NewtonSettings newton_;
  Workspace& ws_;
  State& state_;
  DofMap dofs_;
  SystemMatrix matrix_;
  double load_factor_ = 0.0;
  VectorXd q_start_;
  VectorXd residual_full_;
};

}  // namespace

SolveResult SolveStatic(const Model& model, const StaticSettings& settings,
                        const OutputCallback& output, State* state) {
  if (model.has_free_bodies())
    throw InputError(
        "static analysis: the model has a free rigid body, which has no static equilibrium to "
        "find; make it fixed (motion: fixed) or run a dynamic analysis");
  // The static residual has no contact forces: a contact scene would be solved as if nothing
  // touched. Refused until contact enters the static residual (issue 17).
  if (!model.contact().targets.empty() || model.contact().self_contact)
    throw InputError(
        "static analysis: the scene has contact (targets or self_contact), which the static solver "
        "does not include; run a dynamic analysis to rest, or remove the contact section");
  Workspace ws(model);
  state->v.setZero();
  state->a.setZero();
  state->t = 0.0;
  CalcInternalForces(model, state->q, state->v, ws);
  CalcExternalForces(model, state->q, 0.0, ws);
  EnergyTracker energy(model, ws, *state, /*load_factor=*/0.0, EnergyQuadrature::kLoadPath);
  SolveResult result;
  if (!EmitOutput(output, *state, energy.account(), &result)) return result;

  LoadIncrement increment(model, settings.newton, ws, *state);
  NewtonSolver newton(settings.newton, JacobianUpdate::kEveryIteration);
  const double nominal = 1.0 / settings.load_steps;
  double load_factor = 0.0;
  double step = nominal;
  int cuts_in_a_row = 0;
  while (load_factor < 1.0 - 1e-12) {
    // The last increment lands on λ = 1 exactly (no round-off from summing increments).
    const double target = load_factor + step >= 1.0 - 1e-12 ? 1.0 : load_factor + step;
    increment.Begin(target);
    NewtonResult newton_result = newton.Solve(increment);
    result.statistics.newton_iterations += newton_result.iterations;
    result.statistics.jacobian_updates += newton_result.jacobian_updates;
    if (!newton_result.converged) {
      increment.Reset();
      if (++cuts_in_a_row > settings.max_step_cuts) {
        result.completed = false;
        result.message = fmt::format(
            "static solve failed at load factor {:.6g} (increment {:.3g} after {} cuts): {}",
            target, step, settings.max_step_cuts, newton_result.failure);
        return result;
      }
      ++result.statistics.step_cuts;
      step *= 0.5;
      continue;
    }
    load_factor = target;
    state->t = load_factor;
    ++result.statistics.steps;
    if (cuts_in_a_row == 0) step = std::min(2.0 * step, nominal);
    cuts_in_a_row = 0;
    CalcInternalForces(model, state->q, state->v, ws);
    CalcExternalForces(model, state->q, load_factor, ws);
    energy.Advance(model, ws, *state, load_factor);
    if (!EmitOutput(output, *state, energy.account(), &result)) return result;
    if (StopIfInterrupted(output, *state, energy.account(), /*written=*/true, &result))
      return result;
  }
  return result;
}

}  // namespace ancfnet
