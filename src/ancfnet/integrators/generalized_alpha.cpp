#include "ancfnet/integrators/generalized_alpha.hpp"

#include "ancfnet/integrators/initial_acceleration.hpp"

namespace ancfnet {

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::FromSpectralRadius(double rho) {
  GeneralizedAlphaCoefficients c;
  c.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
  c.alpha_f = rho / (rho + 1.0);
  c.gamma = 0.5 + c.alpha_f - c.alpha_m;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

// The unknown is a_{n+1}; q and v follow (Arnold & Brüls 2007, eq. 9):
//   (1 − α_m) ā_{n+1} = (1 − α_f) a_{n+1} + α_f a_n − α_m ā_n
//   q_{n+1} = q_n + h v_n + h² (½ − β) ā_n + h² β ā_{n+1}
//   v_{n+1} = v_n + h (1 − γ) ā_n + h γ ā_{n+1}
// so ∂q/∂a = β' = h² β (1 − α_f)/(1 − α_m) and ∂v/∂a = γ' = h γ (1 − α_f)/(1 − α_m), and the
// residual R = M a + Q_int(q, v) − Q_ext(q, t) has the iteration matrix M + γ' C + β' K.
class GeneralizedAlphaIntegrator::StepProblem {
 public:
  StepProblem(GeneralizedAlphaIntegrator& owner, double h, State& state)
      : owner_(owner), state_(state) {
    const GeneralizedAlphaCoefficients& c = owner.coefficients_;
    const double ratio = (1.0 - c.alpha_f) / (1.0 - c.alpha_m);
    beta_prime_ = h * h * c.beta * ratio;
    gamma_prime_ = h * c.gamma * ratio;
    h_ = h;
  }

  Index size() const { return owner_.dofs_.num_unknowns(); }

  // Starting guess of a_{n+1}, then q and v from the update formulas.
  void Reset() {
    const GeneralizedAlphaCoefficients& c = owner_.coefficients_;
    const State& prev = owner_.previous_;
    const VectorXd& a_bar = owner_.a_bar_;
    state_.t = prev.t + h_;
    state_.a = prev.a;
    if (owner_.predictor_ == Predictor::kConstantPosition) {
      // a_{n+1} such that q_{n+1} = q_n: ā_{n+1} = −(h v_n + h² (½ − β) ā_n) / (h² β).
      for (Index i : owner_.dofs_.coordinates()) {
        const double a_bar_next =
            -(h_ * prev.v[i] + h_ * h_ * (0.5 - c.beta) * a_bar[i]) / (h_ * h_ * c.beta);
        state_.a[i] = ((1.0 - c.alpha_m) * a_bar_next - c.alpha_f * prev.a[i] +
                       c.alpha_m * a_bar[i]) / (1.0 - c.alpha_f);
      }
    }
    for (Index i : owner_.dofs_.coordinates()) {
      const double a_bar_next =
          ((1.0 - c.alpha_f) * state_.a[i] + c.alpha_f * prev.a[i] - c.alpha_m * a_bar[i]) /
          (1.0 - c.alpha_m);
      state_.q[i] = prev.q[i] + h_ * prev.v[i] +
                    h_ * h_ * ((0.5 - c.beta) * a_bar[i] + c.beta * a_bar_next);
      state_.v[i] = prev.v[i] + h_ * ((1.0 - c.gamma) * a_bar[i] + c.gamma * a_bar_next);
    }
    owner_.dofs_.AdvanceMoving(prev.q, prev.v, h_, &state_.q);
  }

  void CalcResidual(VectorXd* r) {
    CalcInternalForces(owner_.model_, state_.q, state_.v, owner_.ws_);
    CalcExternalForces(owner_.model_, state_.q, 1.0, owner_.ws_);
    owner_.mass_times_a_.noalias() = owner_.mass_ * state_.a;
    owner_.residual_full_ =
        owner_.mass_times_a_ + owner_.ws_.internal_force - owner_.ws_.external_force;
    owner_.dofs_.Restrict(owner_.residual_full_, r);
  }

  const SparseMatrixd& CalcIterationMatrix() {
    AssembleIterationMatrix(owner_.model_, state_.q, state_.v,
                            {.mass = 1.0, .damping = gamma_prime_, .stiffness = beta_prime_}, 1.0,
                            owner_.ws_, &owner_.iteration_matrix_);
    return owner_.iteration_matrix_.matrix();
  }

  void ApplyIncrement(const VectorXd& da, double scale) {
    owner_.dofs_.AddExpanded(da, scale, &state_.a);
    owner_.dofs_.AddExpanded(da, scale * beta_prime_, &state_.q);
    owner_.dofs_.AddExpanded(da, scale * gamma_prime_, &state_.v);
  }

  // Convergence is judged on the position increment Δq = β' Δa.
  double IncrementNorm(const VectorXd& da) const {
    const NewtonSettings& s = owner_.newton_settings_;
    return WeightedRmsNorm(da, state_.q, owner_.dofs_.coordinates(), beta_prime_,
                           s.relative_tolerance, s.absolute_tolerance);
  }

 private:
  GeneralizedAlphaIntegrator& owner_;
  State& state_;
  double h_ = 0.0;
  double beta_prime_ = 0.0;
  double gamma_prime_ = 0.0;
};

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const Model& model,
                                                       const DynamicSettings& settings)
    : model_(model),
      coefficients_(GeneralizedAlphaCoefficients::FromSpectralRadius(settings.spectral_radius)),
      ws_(model),
      dofs_(DofMap::FreeCoordinates(model)),
      iteration_matrix_(model, dofs_),
      newton_(settings.newton, settings.jacobian_update, /*line_search=*/false),
      newton_settings_(settings.newton),
      residual_full_(model.num_dofs()),
      mass_times_a_(model.num_dofs()) {
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix mass(model, all);
  AssembleMassMatrix(model, ws_, &mass);
  mass_ = mass.matrix();
}

bool GeneralizedAlphaIntegrator::Initialize(State* state) {
  ws_.link_broken = state->link_broken;
  newton_.InvalidateJacobian();  // also called after a failure: the links have changed
  if (!CalcInitialAcceleration(model_, dofs_, ws_, state)) return false;
  a_bar_ = state->a;
  previous_ = *state;
  return true;
}

StepOutcome GeneralizedAlphaIntegrator::Step(double h, State* state) {
  previous_.t = state->t;
  previous_.q = state->q;
  previous_.v = state->v;
  previous_.a = state->a;
  if (h != last_h_) newton_.InvalidateJacobian();  // the iteration matrix depends on h
  last_h_ = h;
  StepProblem problem(*this, h, *state);
  predictor_ = Predictor::kConstantAcceleration;
  problem.Reset();
  NewtonResult result = newton_.Solve(problem);
  if (!result.converged) {
    // Stiff modes excited by a sudden load carry large, sign-alternating accelerations that
    // make a_{n+1} = a_n a poor guess; q_{n+1} = q_n is close in those modes. One retry with it
    // before the time loop has to cut the step.
    predictor_ = Predictor::kConstantPosition;
    problem.Reset();
    const NewtonResult first = result;
    result = newton_.Solve(problem);
    result.iterations += first.iterations;
    result.jacobian_updates += first.jacobian_updates;
  }
  StepOutcome outcome{.accepted = result.converged,
                      .newton_iterations = result.iterations,
                      .jacobian_updates = result.jacobian_updates,
                      .failure = result.failure};
  if (!result.converged) {
    state->t = previous_.t;
    state->q = previous_.q;
    state->v = previous_.v;
    state->a = previous_.a;
    return outcome;
  }
  const GeneralizedAlphaCoefficients& c = coefficients_;
  for (Index i : dofs_.coordinates())
    a_bar_[i] = ((1.0 - c.alpha_f) * state->a[i] + c.alpha_f * previous_.a[i] -
                 c.alpha_m * a_bar_[i]) / (1.0 - c.alpha_m);
  // Forces at the accepted state, for the energy account.
  CalcInternalForces(model_, state->q, state->v, ws_);
  CalcExternalForces(model_, state->q, 1.0, ws_);
  return outcome;
}

}  // namespace ancfnet
