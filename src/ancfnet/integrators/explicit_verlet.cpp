#include "ancfnet/integrators/explicit_verlet.hpp"

#include <cmath>
#include <limits>

namespace ancfnet {

ExplicitVerletIntegrator::ExplicitVerletIntegrator(const Model& model)
    : model_(model), ws_(model), dofs_(DofMap::FreeCoordinates(model)) {}

bool ExplicitVerletIntegrator::Initialize(State* state) {
  SystemMatrix mass(model_, dofs_);
  AssembleMassMatrix(model_, ws_, &mass);
  if (!mass_solver_.Factorize(mass.matrix())) return false;
  CalcAcceleration(state->q, state->v, &state->a);
  return true;
}

void ExplicitVerletIntegrator::CalcAcceleration(const VectorXd& q, const VectorXd& v,
                                                VectorXd* a) {
  CalcInternalForces(model_, q, v, ws_);
  CalcExternalForces(model_, q, 1.0, ws_);
  dofs_.Restrict(ws_.external_force - ws_.internal_force, &rhs_);
  mass_solver_.Solve(rhs_, &a_free_);
  a->setZero();
  dofs_.AddExpanded(a_free_, 1.0, a);
}

StepOutcome ExplicitVerletIntegrator::Step(double h, State* state) {
  previous_ = *state;
  state->v += 0.5 * h * state->a;
  state->q += h * state->v;
  CalcAcceleration(state->q, state->v, &state->a);
  state->v += 0.5 * h * state->a;
  state->t += h;
  StepOutcome outcome;
  outcome.accepted = true;
  if (!state->q.allFinite() || !state->v.allFinite()) {
    *state = previous_;
    outcome.accepted = false;
    outcome.failure = "non-finite state (explicit step above the stability limit?)";
    return outcome;
  }
  // Viscous forces for the energy account at the full-step velocity.
  CalcInternalForces(model_, state->q, state->v, ws_);
  return outcome;
}

double ExplicitVerletIntegrator::EstimateCriticalStep() const {
  double critical = std::numeric_limits<double>::infinity();
  for (const CableElement& element : model_.elements()) {
    const CableElementParameters& p = element.parameters;
    const double wave_speed = std::sqrt(p.axial_stiffness / p.mass_per_length);
    critical = std::min(critical, p.length / wave_speed);
  }
  return critical;
}

}  // namespace ancfnet
