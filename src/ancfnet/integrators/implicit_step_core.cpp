#include "ancfnet/integrators/implicit_step_core.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/integrators/initial_acceleration.hpp"
#include "ancfnet/model/coordinate_scales.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {

ImplicitStepCore::ImplicitStepCore(const Model& model, const DynamicSettings& settings)
    : model_(model),
      ws_(model),
      forces_(model, ws_, settings.contact_couplings.near_factor),
      dofs_(DofMap::FreeCoordinates(model)),
      iteration_matrix_(model, dofs_),
      constraints_(model),
      newton_(settings.newton, settings.jacobian_update),
      newton_settings_(settings.newton),
      increment_weights_(CalcIncrementWeights(CalcCoordinateScales(model), dofs_.coordinates(),
                                              settings.newton.relative_tolerance,
                                              settings.newton.absolute_tolerance)),
      smallest_step_(settings.smallest_step()),
      residual_full_(model.num_dofs()) {
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix mass(model, all);
  AssembleMassMatrix(model, ws_, &mass);
  mass_ = mass.matrix();
  iteration_matrix_.set_contact_coupling_settings(settings.contact_couplings);
}

bool ImplicitStepCore::Initialize(State* state) {
  TakeOver(*state);
  newton_.InvalidateJacobian();
  if (!CalcInitialAcceleration(model_, dofs_, forces_, ws_, state)) return false;
  previous_ = *state;
  return true;
}

void ImplicitStepCore::SaveCheckpoint(ArchiveWriter* out) const {
  out->Write(last_h_);
  iteration_matrix_.SaveContactCouplings(out);
  newton_.SaveCheckpoint(out);
}

void ImplicitStepCore::Resume(const State& state, ArchiveReader* in) {
  TakeOver(state);
  previous_ = state;
  last_h_ = in->Read<double>();
  iteration_matrix_.LoadContactCouplings(in);
  newton_.LoadCheckpoint(in);
}

void ImplicitStepCore::TakeOver(const State& state) {
  ws_.link_broken = state.link_broken;
  ws_.body_rotation = state.body_rotation;
  ws_.joint_history = state.joint_history;
}

void ImplicitStepCore::BeginStep(double h, const State& state) {
  previous_.t = state.t;
  previous_.q = state.q;
  previous_.v = state.v;
  previous_.a = state.a;
  previous_.multipliers = state.multipliers;
  previous_.contact_history = state.contact_history;
  previous_.body_rotation = state.body_rotation;
  ws_.body_rotation = state.body_rotation;
  ws_.joint_history = state.joint_history;
  if (h != last_h_) newton_.InvalidateJacobian();
  last_h_ = h;
}

bool ImplicitStepCore::DetectContacts(double h, const State& state) {
  forces_.FindContacts(state, h, /*with_step_size=*/true);
  if (!forces_.has_contact()) return false;
  forces_.FindCouplings(state.q, state.v, h, iteration_matrix_, &required_couplings_,
                        &near_couplings_);
  if (!iteration_matrix_.UpdateContactCouplings(required_couplings_, near_couplings_)) return false;
  newton_.InvalidatePattern();
  return true;
}

void ImplicitStepCore::SetStepEnd(const VectorXd* q_end) {
  forces_.SetStep(previous_.q, previous_.v, q_end, ws_);
}

std::string ImplicitStepCore::CheckStep(const VectorXd& q, const VectorXd& v) const {
  return forces_.CheckStep(previous_.q, previous_.v, q, v,
                           /*check_targets=*/0.5 * last_h_ >= smallest_step_);
}

void ImplicitStepCore::CalcResidual(const VectorXd& q, const VectorXd& v, const VectorXd& a,
                                    const VectorXd& multipliers, double constraint_scale,
                                    VectorXd* r) {
  CalcForces(q, v);
  residual_full_.noalias() = mass_ * a;
  residual_full_ += ws_.internal_force - ws_.external_force;
  if (constraints_.empty()) {
    dofs_.Restrict(residual_full_, r);
    return;
  }
  constraints_.Evaluate(q, v, ws_.body_rotation);
  constraints_.AddReaction(multipliers, &residual_full_);
  dofs_.Restrict(residual_full_, &residual_free_);
  r->resize(dofs_.num_unknowns() + constraints_.size());
  *r << residual_free_, constraints_.violation() / constraint_scale;
}

const SparseMatrixd& ImplicitStepCore::CalcIterationMatrix(const VectorXd& q, const VectorXd& v,
                                                           const VectorXd& multipliers,
                                                           const IterationWeights& weights) {
  forces_.AssembleIterationMatrix(q, v, previous_.contact_history, weights, 1.0, ws_,
                                  &iteration_matrix_);
  // The forces it leaves in ws_ are not used: Newton takes them from CalcResidual.
  if (constraints_.empty()) return iteration_matrix_.matrix();
  // Scaled index-3 form (Bottasso, Bauchau & Cardona 2007; Arnold & Brüls 2007): the
  // rows g/c_K have the derivative G with respect to the unknown, the columns Gᵀ act on λ.
  constraints_.Evaluate(q, v, ws_.body_rotation);
  constraints_.AddGeometricStiffness(multipliers, weights.stiffness, &iteration_matrix_);
  constraints_.AssembleBorderedMatrix(iteration_matrix_.matrix(), dofs_, &bordered_);
  return bordered_;
}

double ImplicitStepCore::ConstraintViolation(const VectorXd& q, const VectorXd& v) {
  if (constraints_.empty()) return 0.0;
  constraints_.Evaluate(q, v, ws_.body_rotation);
  return constraints_.MaxViolation();
}

void ImplicitStepCore::CalcForces(const VectorXd& q, const VectorXd& v) {
  forces_.Calc(q, v, previous_.contact_history, 1.0, ws_);
}

void ImplicitStepCore::AcceptStep(State* state) {
  forces_.UpdateHistories(state);
  ws_.joint_history = state->joint_history;
  RebaseBodyRotations(model_, state);
  ws_.body_rotation = state->body_rotation;
}

void ImplicitStepCore::CalcDriveForce(const State& state) {
  const std::vector<Index>& prescribed = dofs_.prescribed_coordinates();
  if (prescribed.empty()) return;
  residual_full_.noalias() = mass_ * state.a;
  if (!constraints_.empty()) {
    // The joints' reactions on the driven coordinates are part of what the drive supplies.
    constraints_.Evaluate(state.q, state.v, ws_.body_rotation);
    constraints_.AddReaction(state.multipliers, &residual_full_);
  }
  for (Index i : prescribed)
    ws_.drive_force[i] = residual_full_[i] + ws_.internal_force[i] - ws_.external_force[i];
}

double ImplicitStepCore::EnergyScale(const VectorXd& q, const VectorXd& v) const {
  double kinetic = 0.0;
  for (Index k = 0; k < mass_.outerSize(); ++k)
    for (SparseMatrixd::InnerIterator it(mass_, k); it; ++it)
      kinetic += 0.5 * v[it.row()] * it.value() * v[it.col()];
  double internal = 0.0;
  double external = 0.0;
  for (Index i = 0; i < q.size(); ++i) {
    const double dq = q[i] - previous_.q[i];
    internal += dq * ws_.internal_force[i];
    external += dq * ws_.external_force[i];
  }
  return kinetic + std::abs(internal) + std::abs(external);
}

double ImplicitStepCore::IncrementNorm(const VectorXd& da, double scale) const {
  if (constraints_.empty()) return WeightedRmsNorm(da, increment_weights_, scale);
  return std::max(WeightedRmsNorm(da.head(dofs_.num_unknowns()), increment_weights_, scale),
                  constraints_.ScaledViolation(newton_settings_.relative_tolerance,
                                               newton_settings_.absolute_tolerance));
}

}  // namespace ancfnet
