#include "ancfnet/integrators/explicit_verlet.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {

ExplicitVerletIntegrator::ExplicitVerletIntegrator(const Model& model)
    : model_(model), ws_(model), forces_(model, ws_), dofs_(DofMap::FreeCoordinates(model)) {
  const auto& friction = model.contact().friction;
  if (friction && friction->kind == FrictionLawKind::kLuGre)
    throw InputError(
        "contact friction: the LuGre law needs an implicit integrator (generalized_alpha or "
        "implicit_midpoint), not explicit_verlet");
  for (const ClearanceJoint& joint : model.clearance_joints())
    if (joint.friction && joint.friction->kind == FrictionLawKind::kLuGre)
      throw InputError(fmt::format(
          "joint '{}' friction: the LuGre law needs an implicit integrator (generalized_alpha or "
          "implicit_midpoint), not explicit_verlet",
          joint.name));
}

bool ExplicitVerletIntegrator::Initialize(State* state) {
  if (!Prepare(*state)) return false;
  critical_step_ = EstimateCriticalStep(state->q);
  critical_step_time_ = state->t;
  forces_.FindContacts(*state, 0.0, /*with_step_size=*/false);
  CalcAcceleration(state->q, state->v, &state->a);
  return true;
}

void ExplicitVerletIntegrator::SaveCheckpoint(ArchiveWriter* out) const {
  out->Write(critical_step_);
  out->Write(critical_step_time_);
}

bool ExplicitVerletIntegrator::Resume(const State& state, ArchiveReader* in) {
  critical_step_ = in->Read<double>();
  critical_step_time_ = in->Read<double>();
  return Prepare(state);
}

bool ExplicitVerletIntegrator::Prepare(const State& state) {
  ws_.link_broken = state.link_broken;
  ws_.body_rotation = state.body_rotation;
  ws_.joint_history = state.joint_history;
  contact_history_ = state.contact_history;
  SystemMatrix mass(model_, dofs_);
  AssembleMassMatrix(model_, ws_, &mass);
  return mass_solver_.Factorize(mass.matrix());
}

void ExplicitVerletIntegrator::CalcAcceleration(const VectorXd& q, const VectorXd& v, VectorXd* a) {
  forces_.Calc(q, v, contact_history_, 1.0, ws_);
  net_force_ = ws_.external_force - ws_.internal_force;
  dofs_.Restrict(net_force_, &rhs_);
  mass_solver_.Solve(rhs_, &a_free_);
  a->setZero();
  dofs_.AddExpanded(a_free_, 1.0, a);
}

StepOutcome ExplicitVerletIntegrator::Step(double h, State* state) {
  previous_ = *state;
  forces_.FindContacts(*state, h, /*with_step_size=*/false);
  state->v += 0.5 * h * state->a;
  state->q += h * state->v;
  ApplyPrescribedMotion(model_.prescribed(), state->t + h, &state->q, &state->v, nullptr);
  CalcAcceleration(state->q, state->v, &state->a);
  state->v += 0.5 * h * state->a;
  state->t += h;
  StepOutcome outcome;
  outcome.accepted = true;
  if (!state->q.allFinite() || !state->v.allFinite()) {
    *state = previous_;
    outcome.accepted = false;
    outcome.failure =
        h > critical_step_
            ? fmt::format(
                  "non-finite state: h = {:.3g} s is above the stability limit of the "
                  "elements, about {:.3g} s (2/ω_max at t = {:.9g} s)",
                  h, critical_step_, critical_step_time_)
            : fmt::format(
                  "non-finite state at h = {:.3g} s, below the stability limit of the "
                  "elements (about {:.3g} s, 2/ω_max at t = {:.9g} s): a stiffer force (contact, "
                  "a link, a body) or a motion that ran away made the run diverge",
                  h, critical_step_, critical_step_time_);
    return outcome;
  }
  outcome.failure =
      forces_.CheckStep(previous_.q, previous_.v, state->q, state->v, /*check_targets=*/false);
  if (!outcome.failure.empty()) {
    *state = previous_;
    outcome.accepted = false;
    return outcome;
  }
  forces_.UpdateHistories(state);
  contact_history_ = state->contact_history;
  ws_.joint_history = state->joint_history;
  // Bodies: ψ_{n+1} = h ω_{n+½} is the Lie-group increment; rebase R_ref on it.
  RebaseBodyRotations(model_, state);
  ws_.body_rotation = state->body_rotation;
  // Viscous forces for the energy account at the full-step velocity.
  forces_.Calc(state->q, state->v, contact_history_, 1.0, ws_);
  return outcome;
}

double ExplicitVerletIntegrator::EstimateCriticalStep(const VectorXd& q) const {
  double omega_max_squared = 0.0;
  Matrix12d stiffness;
  const Vector12d no_velocity = Vector12d::Zero();
  for (std::size_t i = 0; i < model_.elements().size(); ++i) {
    const CableElement& element = model_.elements()[i];
    if (element.beam >= 0) continue;  // its stiffness is the beam's, below
    const Vector12d e = model_.Gather(element, q);
    CalcCableInternalForce(element.parameters, e, no_velocity, {.stiffness = &stiffness});
    // Symmetric part: the tangent of a conservative element is symmetric up to round-off.
    const Matrix12d k = 0.5 * (stiffness + stiffness.transpose());
    const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix12d> eigen(k, ws_.element_mass[i],
                                                                    Eigen::EigenvaluesOnly);
    omega_max_squared = std::max(omega_max_squared, eigen.eigenvalues().maxCoeff());
  }
  // A beam element against its whole consistent mass (centre line and rotary inertia): its
  // highest frequencies are those of the cross-section's own deformation (docs/theory.md,
  // "Explicit velocity Verlet").
  Matrix24d beam_stiffness;
  const Vector24d no_beam_velocity = Vector24d::Zero();
  for (const BeamElement& beam : model_.beam_elements()) {
    CalcBeamInternalForce(beam.parameters, model_.Gather(beam, q), no_beam_velocity,
                          {.stiffness = &beam_stiffness});
    const Matrix24d k = 0.5 * (beam_stiffness + beam_stiffness.transpose());
    const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix24d> eigen(
        k, CalcBeamMassMatrix(beam.parameters), Eigen::EigenvaluesOnly);
    omega_max_squared = std::max(omega_max_squared, eigen.eigenvalues().maxCoeff());
  }
  return omega_max_squared > 0.0 ? 2.0 / std::sqrt(omega_max_squared)
                                 : std::numeric_limits<double>::infinity();
}

}  // namespace ancfnet
