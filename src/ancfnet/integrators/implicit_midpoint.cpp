#include "ancfnet/integrators/implicit_midpoint.hpp"

#include <cmath>

namespace ancfnet {

// The unknown is the mean acceleration a = (v_{n+1} − v_n)/h, so that
//   v_{n+½} = v_n + (h/2) a,   q_{n+½} = q_n + (h/2) v_n + (h²/4) a,
// and the residual R = M a + Q_int(q_{n+½}, v_{n+½}) − Q_ext(q_{n+½}) has the iteration matrix
// M + (h/2) C + (h²/4) K.
class ImplicitMidpointIntegrator::StepProblem {
 public:
  StepProblem(ImplicitMidpointIntegrator& owner, double h, State& state)
      : core_(owner.core_), mid_(owner.midpoint_), end_(owner.end_), state_(state), h_(h) {}

  Index size() const { return core_.dofs().num_unknowns(); }

  // Starting guess: the mean acceleration of the previous step.
  void Reset() {
    const State& prev = core_.previous();
    state_.a = prev.a;
    mid_.t = prev.t + 0.5 * h_;
    mid_.q = prev.q;
    mid_.v = prev.v;
    for (Index i : core_.dofs().coordinates()) {
      mid_.v[i] = prev.v[i] + 0.5 * h_ * state_.a[i];
      mid_.q[i] = prev.q[i] + 0.5 * h_ * prev.v[i] + 0.25 * h_ * h_ * state_.a[i];
    }
    // Prescribed coordinates: their values at the end go into the state, the means of both ends
    // into the midpoint, and (v_{n+1} − v_n)/h into the mean acceleration.
    ApplyPrescribedMotion(core_.model().prescribed(), prev.t + h_, &state_.q, &state_.v, nullptr);
    for (Index i : core_.dofs().prescribed_coordinates()) {
      mid_.q[i] = 0.5 * (prev.q[i] + state_.q[i]);
      mid_.v[i] = 0.5 * (prev.v[i] + state_.v[i]);
      state_.a[i] = (state_.v[i] - prev.v[i]) / h_;
    }
  }

  // Ideal joints are refused (SolveDynamic): no multipliers.
  void CalcResidual(VectorXd* r) {
    end_.noalias() = 2.0 * mid_.q - core_.previous().q;
    core_.CalcResidual(mid_.q, mid_.v, state_.a, state_.multipliers, 1.0, r);
  }

  const SparseMatrixd& CalcIterationMatrix() {
    return core_.CalcIterationMatrix(
        mid_.q, mid_.v, state_.multipliers, {.mass = 1.0, .damping = 0.5 * h_, .stiffness = 0.25 * h_ * h_});
  }

  void ApplyIncrement(const VectorXd& da, double scale) {
    core_.dofs().AddExpanded(da, scale, &state_.a);
    core_.dofs().AddExpanded(da, scale * 0.25 * h_ * h_, &mid_.q);
    core_.dofs().AddExpanded(da, scale * 0.5 * h_, &mid_.v);
  }

  // Convergence is judged on the increment of the end position, Δq_{n+1} = (h²/2) Δa.
  double IncrementNorm(const VectorXd& da) const { return core_.IncrementNorm(da, 0.5 * h_ * h_); }
  // The residual is taken at the midpoint, which moves by (h²/4) Δa.
  double IncrementEnergy(const VectorXd& da, const VectorXd& r) const {
    return 0.25 * h_ * h_ * std::abs(da.dot(r));
  }
  // Over the whole step, q_n to q_{n+1} (end_, set by CalcResidual): the balance error of the
  // step, whose forces are discrete gradients over it.
  double ResidualWork(const VectorXd& r) const { return core_.ResidualWork(end_, r); }
  double EnergyScale() const { return core_.EnergyScale(mid_.q, mid_.v); }

 private:
  ImplicitStepCore& core_;
  State& mid_;
  VectorXd& end_;
  State& state_;
  double h_ = 0.0;
};

ImplicitMidpointIntegrator::ImplicitMidpointIntegrator(const Model& model,
                                                       const DynamicSettings& settings)
    : core_(model, settings) {}

bool ImplicitMidpointIntegrator::Initialize(State* state) {
  if (!core_.Initialize(state)) return false;
  midpoint_ = *state;
  return true;
}

StepOutcome ImplicitMidpointIntegrator::Step(double h, State* state) {
  core_.BeginStep(h, *state);
  const bool rebuilt = core_.DetectContacts(h, *state);
  StepProblem problem(*this, h, *state);
  problem.Reset();
  end_ = state->q;
  core_.SetStepEnd(&end_);
  const NewtonResult result = core_.Solve(problem);
  StepOutcome outcome{.accepted = result.converged,
                      .newton_iterations = result.iterations,
                      .jacobian_updates = result.jacobian_updates,
                      .pattern_rebuilds = rebuilt ? 1 : 0,
                      .failure = result.failure};
  const State& previous = core_.previous();
  if (result.converged) {
    // The end of the step mirrors the start about the midpoint.
    state->t = previous.t + h;
    for (Index i : core_.dofs().coordinates()) {
      state->q[i] = 2.0 * midpoint_.q[i] - previous.q[i];
      state->v[i] = 2.0 * midpoint_.v[i] - previous.v[i];
    }
    outcome.failure = core_.CheckStep(state->q, state->v);
    outcome.accepted = outcome.failure.empty();
  }
  if (!outcome.accepted) {
    state->t = previous.t;
    state->q = previous.q;
    state->v = previous.v;
    state->a = previous.a;
    return outcome;
  }
  // Forces at the converged midpoint, for the energy account (before the bodies' rotations are
  // rebased: ψ_{n+½} is relative to R_ref of t_n), and the drive's there: the residual's rows of
  // the prescribed coordinates, M a + Q_int − Q_ext at (q_{n+½}, v_{n+½}) with the step's mean
  // acceleration, whose work over q_{n+1} − q_n closes the discrete kinetic-energy balance.
  end_ = state->q;
  core_.CalcForces(midpoint_.q, midpoint_.v);
  midpoint_.a = state->a;
  core_.CalcDriveForce(midpoint_);
  core_.AcceptStep(state);
  return outcome;
}

}  // namespace ancfnet
