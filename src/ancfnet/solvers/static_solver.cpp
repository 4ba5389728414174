#include "ancfnet/solvers/static_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/model/coordinate_scales.hpp"
#include "ancfnet/solvers/newton.hpp"
#include "ancfnet/solvers/system_forces.hpp"

namespace ancfnet {
namespace {

// One load increment as a Newton problem: R(q) = Q_int(q) − λ Q_ext(q) over the unknowns. With
// ideal joints the unknowns are (q, μ), μ the joints' multipliers, and the problem is bordered
// (Géradin & Cardona 2001):
//   R = (Q_int − λ Q_ext + Gᵀ μ, g),   ∂R/∂(q, μ) = [K + ∂(Gᵀμ)/∂q  Gᵀ; G  0].
class LoadIncrement {
 public:
  LoadIncrement(const Model& model, const NewtonSettings& newton, const SystemForces& forces,
                Workspace& ws, State& state)
      : model_(model),
        newton_(newton),
        forces_(forces),
        ws_(ws),
        state_(state),
        dofs_(DofMap::FreeCoordinates(model)),
        matrix_(model, dofs_),
        constraints_(model),
        increment_weights_(CalcIncrementWeights(CalcCoordinateScales(model), dofs_.coordinates(),
                                                newton.relative_tolerance,
                                                newton.absolute_tolerance)),
        q_start_(state.q),
        multipliers_start_(state.multipliers),
        residual_full_(state.q.size()) {}

  void Begin(double load_factor) {
    load_factor_ = load_factor;
    q_start_ = state_.q;
    multipliers_start_ = state_.multipliers;
  }
  Index size() const { return dofs_.num_unknowns() + constraints_.size(); }
  void Reset() {
    state_.q = q_start_;
    state_.multipliers = multipliers_start_;
  }
  void CalcResidual(VectorXd* r) {
    forces_.Calc(state_.q, state_.v, state_.contact_history, load_factor_, ws_);
    residual_full_ = ws_.internal_force - ws_.external_force;
    if (constraints_.empty()) {
      dofs_.Restrict(residual_full_, r);
      return;
    }
    constraints_.Evaluate(state_.q, state_.v, state_.body_rotation);
    constraints_.AddReaction(state_.multipliers, &residual_full_);
    dofs_.Restrict(residual_full_, &residual_free_);
    r->resize(size());
    *r << residual_free_, constraints_.violation();
  }
  const SparseMatrixd& CalcIterationMatrix() {
    forces_.AssembleIterationMatrix(state_.q, state_.v, state_.contact_history, {.stiffness = 1.0},
                                    load_factor_, ws_, &matrix_);
    if (constraints_.empty()) return matrix_.matrix();
    constraints_.Evaluate(state_.q, state_.v, state_.body_rotation);
    constraints_.AddGeometricStiffness(state_.multipliers, 1.0, &matrix_);
    constraints_.AssembleBorderedMatrix(matrix_.matrix(), dofs_, &bordered_);
    return bordered_;
  }
  void ApplyIncrement(const VectorXd& dx, double scale) {
    dofs_.AddExpanded(dx, scale, &state_.q);
    if (!constraints_.empty()) state_.multipliers += scale * dx.tail(constraints_.size());
  }
  // The position increment, and with joints the constraint violation at the iterate the
  // increment was computed at: both must be within the tolerances.
  double IncrementNorm(const VectorXd& dx) const {
    const double norm = WeightedRmsNorm(dx.head(dofs_.num_unknowns()), increment_weights_, 1.0);
    if (constraints_.empty()) return norm;
    return std::max(norm, constraints_.ScaledViolation(newton_.relative_tolerance,
                                                       newton_.absolute_tolerance));
  }
  double IncrementEnergy(const VectorXd& dx, const VectorXd& r) const {
    return std::abs(dx.head(dofs_.num_unknowns()).dot(r.head(dofs_.num_unknowns())));
  }
  // The work of the residual over the increment so far.
  double ResidualWork(const VectorXd& r) const {
    return CalcResidualWork(state_.q, q_start_, dofs_.coordinates(), r);
  }
  // max_i |g_i| at the current state.
  double ConstraintViolation() {
    if (constraints_.empty()) return 0.0;
    constraints_.Evaluate(state_.q, state_.v, state_.body_rotation);
    return constraints_.MaxViolation();
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
  const SystemForces& forces_;
  Workspace& ws_;
  State& state_;
  DofMap dofs_;
  SystemMatrix matrix_;
  JointConstraints constraints_;
  SparseMatrixd bordered_;
  VectorXd increment_weights_;  // of the convergence norm, per unknown (CalcIncrementWeights)
  double load_factor_ = 0.0;
  VectorXd q_start_;
  VectorXd multipliers_start_;
  VectorXd residual_full_;
  VectorXd residual_free_;
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
  // At rest (v = 0) the damping forces vanish: the damping model (the modes of modal damping)
  // is not made.
  const SystemForces forces(model, ws, /*near_factor=*/1.0, /*with_damping=*/false);
  state->v.setZero();
  state->a.setZero();
  state->t = 0.0;
  forces.Calc(state->q, state->v, state->contact_history, 0.0, ws);
  EnergyTracker energy(model, ws, *state, /*load_factor=*/0.0, EnergyQuadrature::kLoadPath);
  SolveResult result;
  if (!EmitOutput(output, *state, energy.account(), &result)) return result;

  LoadIncrement increment(model, settings.newton, forces, ws, *state);
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
    result.statistics.max_constraint_violation =
        std::max(result.statistics.max_constraint_violation, increment.ConstraintViolation());
    ++result.statistics.steps;
    if (cuts_in_a_row == 0) step = std::min(2.0 * step, nominal);
    cuts_in_a_row = 0;
    forces.Calc(state->q, state->v, state->contact_history, load_factor, ws);
    energy.Advance(model, ws, *state, load_factor);
    if (!EmitOutput(output, *state, energy.account(), &result)) return result;
    if (StopIfInterrupted(output, *state, energy.account(), /*written=*/true, &result))
      return result;
  }
  return result;
}

}  // namespace ancfnet
