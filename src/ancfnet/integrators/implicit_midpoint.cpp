#include "ancfnet/integrators/implicit_midpoint.hpp"

#include "ancfnet/integrators/initial_acceleration.hpp"

namespace ancfnet {

// The unknown is the mean acceleration a = (v_{n+1} − v_n)/h, so that
//   v_{n+½} = v_n + (h/2) a,   q_{n+½} = q_n + (h/2) v_n + (h²/4) a,
// and the residual R = M a + Q_int(q_{n+½}, v_{n+½}) − Q_ext(q_{n+½}) has the iteration matrix
// M + (h/2) C + (h²/4) K.
class ImplicitMidpointIntegrator::StepProblem {
 public:
  StepProblem(ImplicitMidpointIntegrator& owner, double h, State& state)
      : owner_(owner), state_(state), h_(h) {}

  Index size() const { return owner_.dofs_.num_unknowns(); }

  // Starting guess: the mean acceleration of the previous step.
  void Reset() {
    const State& prev = owner_.previous_;
    State& mid = owner_.midpoint_;
    state_.a = prev.a;
    mid.t = prev.t + 0.5 * h_;
    mid.q = prev.q;
    mid.v = prev.v;
    for (Index i : owner_.dofs_.coordinates()) {
      mid.v[i] = prev.v[i] + 0.5 * h_ * state_.a[i];
      mid.q[i] = prev.q[i] + 0.5 * h_ * prev.v[i] + 0.25 * h_ * h_ * state_.a[i];
    }
    owner_.dofs_.AdvanceMoving(prev.q, prev.v, 0.5 * h_, &mid.q);
  }

  void CalcResidual(VectorXd* r) {
    const State& mid = owner_.midpoint_;
    CalcInternalForces(owner_.model_, mid.q, mid.v, owner_.ws_);
    CalcExternalForces(owner_.model_, mid.q, 1.0, owner_.ws_);
    owner_.residual_full_.noalias() = owner_.mass_ * state_.a;
    owner_.residual_full_ += owner_.ws_.internal_force - owner_.ws_.external_force;
    owner_.dofs_.Restrict(owner_.residual_full_, r);
  }

  const SparseMatrixd& CalcIterationMatrix() {
    const State& mid = owner_.midpoint_;
    AssembleIterationMatrix(owner_.model_, mid.q, mid.v,
                            {.mass = 1.0, .damping = 0.5 * h_, .stiffness = 0.25 * h_ * h_}, 1.0,
                            owner_.ws_, &owner_.iteration_matrix_);
    return owner_.iteration_matrix_.matrix();
  }

  void ApplyIncrement(const VectorXd& da, double scale) {
    owner_.dofs_.AddExpanded(da, scale, &state_.a);
    owner_.dofs_.AddExpanded(da, scale * 0.25 * h_ * h_, &owner_.midpoint_.q);
    owner_.dofs_.AddExpanded(da, scale * 0.5 * h_, &owner_.midpoint_.v);
  }

  // Convergence is judged on the increment of the end position, Δq_{n+1} = (h²/2) Δa.
  double IncrementNorm(const VectorXd& da) const {
    const NewtonSettings& s = owner_.newton_settings_;
    return WeightedRmsNorm(da, owner_.midpoint_.q, owner_.dofs_.coordinates(), 0.5 * h_ * h_,
                           s.relative_tolerance, s.absolute_tolerance);
  }

 private:
  ImplicitMidpointIntegrator& owner_;
  State& state_;
  double h_ = 0.0;
};

ImplicitMidpointIntegrator::ImplicitMidpointIntegrator(const Model& model,
                                                       const DynamicSettings& settings)
    : model_(model),
      ws_(model),
      dofs_(DofMap::FreeCoordinates(model)),
      iteration_matrix_(model, dofs_),
      newton_(settings.newton, settings.jacobian_update, /*line_search=*/false),
      newton_settings_(settings.newton),
      residual_full_(model.num_dofs()) {
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix mass(model, all);
  AssembleMassMatrix(model, ws_, &mass);
  mass_ = mass.matrix();
}

bool ImplicitMidpointIntegrator::Initialize(State* state) {
  ws_.link_broken = state->link_broken;
  newton_.InvalidateJacobian();  // also called after a failure: the links have changed
  if (!CalcInitialAcceleration(model_, dofs_, ws_, state)) return false;
  previous_ = *state;
  midpoint_ = *state;
  return true;
}

StepOutcome ImplicitMidpointIntegrator::Step(double h, State* state) {
  previous_.t = state->t;
  previous_.q = state->q;
  previous_.v = state->v;
  previous_.a = state->a;
  if (h != last_h_) newton_.InvalidateJacobian();  // the iteration matrix depends on h
  last_h_ = h;
  StepProblem problem(*this, h, *state);
  problem.Reset();
  const NewtonResult result = newton_.Solve(problem);
  const StepOutcome outcome{.accepted = result.converged,
                            .newton_iterations = result.iterations,
                            .jacobian_updates = result.jacobian_updates,
                            .failure = result.failure};
  if (!result.converged) {
    state->a = previous_.a;
    return outcome;
  }
  // The end of the step mirrors the start about the midpoint.
  state->t = previous_.t + h;
  for (Index i : dofs_.coordinates()) {
    state->q[i] = 2.0 * midpoint_.q[i] - previous_.q[i];
    state->v[i] = 2.0 * midpoint_.v[i] - previous_.v[i];
  }
  dofs_.AdvanceMoving(previous_.q, previous_.v, h, &state->q);
  // Forces at the converged midpoint, for the energy account.
  CalcInternalForces(model_, midpoint_.q, midpoint_.v, ws_);
  CalcExternalForces(model_, midpoint_.q, 1.0, ws_);
  return outcome;
}

}  // namespace ancfnet
