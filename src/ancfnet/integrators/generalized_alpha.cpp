#include "ancfnet/integrators/generalized_alpha.hpp"

#include <cmath>

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
// With ideal joints the unknowns are (a_{n+1}, λ_{n+1}) and the equations
//   M a + Q_int − Q_ext + Gᵀλ = 0,   g(q_{n+1})/β' = 0
// the index-3 form with the constraints scaled by 1/β' (Bottasso, Bauchau & Cardona 2007;
// Arnold & Brüls 2007), whose iteration matrix [M + γ' C + β' (K + ∂(Gᵀλ)/∂q)  Gᵀ; G  0]
// stays well conditioned as h → 0 (ImplicitStepCore::CalcIterationMatrix).
class GeneralizedAlphaIntegrator::StepProblem {
 public:
  StepProblem(GeneralizedAlphaIntegrator& owner, double h, State& state)
      : owner_(owner), core_(owner.core_), state_(state), h_(h) {
    const GeneralizedAlphaCoefficients& c = owner.coefficients_;
    const double ratio = (1.0 - c.alpha_f) / (1.0 - c.alpha_m);
    beta_prime_ = h * h * c.beta * ratio;
    gamma_prime_ = h * c.gamma * ratio;
  }

  Index size() const { return core_.dofs().num_unknowns() + core_.num_constraints(); }

  // Starting guess of a_{n+1}, then q and v from the update formulas.
  void Reset() {
    const GeneralizedAlphaCoefficients& c = owner_.coefficients_;
    const State& prev = core_.previous();
    const VectorXd& a_bar = owner_.a_bar_;
    const std::vector<Index>& free = core_.dofs().coordinates();
    state_.t = prev.t + h_;
    state_.a = prev.a;
    state_.multipliers = prev.multipliers;
    if (owner_.predictor_ == Predictor::kConstantPosition) {
      // a_{n+1} such that q_{n+1} = q_n: ā_{n+1} = −(h v_n + h² (½ − β) ā_n) / (h² β).
      for (Index i : free) {
        const double a_bar_next =
            -(h_ * prev.v[i] + h_ * h_ * (0.5 - c.beta) * a_bar[i]) / (h_ * h_ * c.beta);
        state_.a[i] =
            ((1.0 - c.alpha_m) * a_bar_next - c.alpha_f * prev.a[i] + c.alpha_m * a_bar[i]) /
            (1.0 - c.alpha_f);
      }
    }
    for (Index i : free) {
      const double a_bar_next =
          ((1.0 - c.alpha_f) * state_.a[i] + c.alpha_f * prev.a[i] - c.alpha_m * a_bar[i]) /
          (1.0 - c.alpha_m);
      state_.q[i] =
          prev.q[i] + h_ * prev.v[i] + h_ * h_ * ((0.5 - c.beta) * a_bar[i] + c.beta * a_bar_next);
      state_.v[i] = prev.v[i] + h_ * ((1.0 - c.gamma) * a_bar[i] + c.gamma * a_bar_next);
    }
    ApplyPrescribedMotion(core_.model().prescribed(), state_.t, &state_.q, &state_.v, &state_.a);
  }

  void CalcResidual(VectorXd* r) {
    core_.CalcResidual(state_.q, state_.v, state_.a, state_.multipliers, beta_prime_, r);
  }

  const SparseMatrixd& CalcIterationMatrix() {
    return core_.CalcIterationMatrix(
        state_.q, state_.v, state_.multipliers, {.mass = 1.0, .damping = gamma_prime_, .stiffness = beta_prime_});
  }

  void ApplyIncrement(const VectorXd& da, double scale) {
    core_.dofs().AddExpanded(da, scale, &state_.a);
    core_.dofs().AddExpanded(da, scale * beta_prime_, &state_.q);
    core_.dofs().AddExpanded(da, scale * gamma_prime_, &state_.v);
    if (core_.num_constraints() > 0)
      state_.multipliers += scale * da.tail(core_.num_constraints());
  }

  // Convergence is judged on the position increment Δq = β' Δa and the constraints' violation.
  double IncrementNorm(const VectorXd& da) const { return core_.IncrementNorm(da, beta_prime_); }
  double IncrementEnergy(const VectorXd& da, const VectorXd& r) const {
    return beta_prime_ * std::abs(da.dot(r));
  }
  double ResidualWork(const VectorXd& r) const { return core_.ResidualWork(state_.q, r); }
  double EnergyScale() const { return core_.EnergyScale(state_.q, state_.v); }

 private:
  GeneralizedAlphaIntegrator& owner_;
  ImplicitStepCore& core_;
  State& state_;
  double h_ = 0.0;
  double beta_prime_ = 0.0;
  double gamma_prime_ = 0.0;
};

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const Model& model,
                                                       const DynamicSettings& settings)
    : core_(model, settings),
      coefficients_(GeneralizedAlphaCoefficients::FromSpectralRadius(settings.spectral_radius)) {}

bool GeneralizedAlphaIntegrator::Initialize(State* state) {
  if (!core_.Initialize(state)) return false;
  core_.CalcDriveForce(*state);
  a_bar_ = state->a;
  return true;
}

void GeneralizedAlphaIntegrator::SaveCheckpoint(ArchiveWriter* out) const {
  out->Write(a_bar_);
  core_.SaveCheckpoint(out);
}

bool GeneralizedAlphaIntegrator::Resume(const State& state, ArchiveReader* in) {
  in->Read(&a_bar_);
  if (a_bar_.size() != state.a.size()) in->Fail("an auxiliary acceleration of the wrong length");
  core_.Resume(state, in);
  return true;
}

StepOutcome GeneralizedAlphaIntegrator::Step(double h, State* state) {
  core_.BeginStep(h, *state);
  const bool rebuilt = core_.DetectContacts(h, *state);
  StepProblem problem(*this, h, *state);
  predictor_ = Predictor::kConstantAcceleration;
  problem.Reset();
  NewtonResult result = core_.Solve(problem);
  if (!result.converged) {
    // Stiff modes excited by a sudden load carry large, sign-alternating accelerations that
    // make a_{n+1} = a_n a poor guess; q_{n+1} = q_n is close in those modes. One retry with it
    // before the time loop has to cut the step.
    predictor_ = Predictor::kConstantPosition;
    problem.Reset();
    const NewtonResult first = result;
    result = core_.Solve(problem);
    result.iterations += first.iterations;
    result.jacobian_updates += first.jacobian_updates;
  }
  if (result.converged) {
    result.failure = core_.CheckStep(state->q, state->v);
    result.converged = result.failure.empty();
  }
  StepOutcome outcome{.accepted = result.converged,
                      .newton_iterations = result.iterations,
                      .jacobian_updates = result.jacobian_updates,
                      .pattern_rebuilds = rebuilt ? 1 : 0,
                      .failure = result.failure};
  const State& previous = core_.previous();
  if (!result.converged) {
    state->t = previous.t;
    state->q = previous.q;
    state->v = previous.v;
    state->a = previous.a;
    state->multipliers = previous.multipliers;
    return outcome;
  }
  const GeneralizedAlphaCoefficients& c = coefficients_;
  for (Index i : core_.dofs().coordinates())
    a_bar_[i] =
        ((1.0 - c.alpha_f) * state->a[i] + c.alpha_f * previous.a[i] - c.alpha_m * a_bar_[i]) /
        (1.0 - c.alpha_m);
  core_.AcceptStep(state);
  outcome.constraint_violation = core_.ConstraintViolation(state->q, state->v);
  // Forces at the accepted state, and the drive's, for the energy account.
  core_.CalcForces(state->q, state->v);
  core_.CalcDriveForce(*state);
  return outcome;
}

}  // namespace ancfnet
