#include "ancfnet/solvers/system_forces.hpp"

#include "ancfnet/forces/clearance_joint_forces.hpp"

namespace ancfnet {

SystemForces::SystemForces(const Model& model, const Workspace& ws, double near_factor,
                           bool with_damping)
    : model_(model), target_contact_(model), self_contact_(model, near_factor) {
  if (with_damping) damping_.emplace(model);
  target_contact_.SetBodyRotations(&ws.body_rotation);
}

void SystemForces::FindContacts(const State& state, double h, bool with_step_size) {
  if (with_step_size) {
    target_contact_.SetStepSize(h);
    joint_step_ = h;
  }
  if (!self_contact_.empty()) self_contact_.FindCandidates(state, h);
}

void SystemForces::FindCouplings(const VectorXd& q, const VectorXd& v, double h,
                                 const SystemMatrix& matrix,
                                 std::vector<std::pair<Index, Index>>* required,
                                 std::vector<std::pair<Index, Index>>* near) {
  required->clear();
  near->clear();
  auto append = [](const std::vector<std::pair<Index, Index>>& from,
                   std::vector<std::pair<Index, Index>>* to) {
    to->insert(to->end(), from.begin(), from.end());
  };
  if (!self_contact_.empty()) {
    append(self_contact_.coupled_owners(), required);
    append(self_contact_.near_owners(), near);
  }
  if (!target_contact_.empty()) {
    target_contact_.FindBodyCouplings(q, v, h, matrix, &body_couplings_);
    append(body_couplings_, required);
  }
}

void SystemForces::SetStep(const VectorXd& q_start, const VectorXd& v_start, const VectorXd* q_end,
                           Workspace& ws) {
  step_end_ = q_end;
  if (q_end) BeginStepForceCorrections(model_, q_start, ws);
  if (!target_contact_.empty()) target_contact_.SetStep(q_start, v_start, q_end);
  if (!self_contact_.empty()) self_contact_.SetStep(q_start, q_end);
}

void SystemForces::Calc(const VectorXd& q, const VectorXd& v,
                        const std::vector<ContactPairHistory>& history, double load_factor,
                        Workspace& ws) const {
  ws.joint_step = joint_step_;
  CalcInternalForces(model_, q, v, ws);
  if (step_end_) AddStepForceCorrections(model_, *step_end_, ws);
  if (damping_) damping_->AddForces(v, ws);
  ws.contact_energy = 0.0;
  if (!target_contact_.empty()) target_contact_.AddForces(q, v, history, ws);
  if (!self_contact_.empty()) self_contact_.AddForces(q, v, ws);
  CalcExternalForces(model_, q, load_factor, ws);
}

void SystemForces::AssembleIterationMatrix(const VectorXd& q, const VectorXd& v,
                                           const std::vector<ContactPairHistory>& history,
                                           const IterationWeights& weights, double load_factor,
                                           Workspace& ws, SystemMatrix* matrix) const {
  ws.joint_step = joint_step_;
  ancfnet::AssembleIterationMatrix(model_, q, v, weights, load_factor, ws, matrix);
  if (step_end_) AddStepForceCorrectionJacobians(model_, *step_end_, weights.stiffness, ws, matrix);
  if (damping_) damping_->AddRayleighJacobian(weights.damping, matrix);
  if (!target_contact_.empty()) target_contact_.AddJacobian(q, v, history, weights, matrix);
  if (!self_contact_.empty()) self_contact_.AddJacobian(q, v, weights, matrix);
}

std::string SystemForces::CheckStep(const VectorXd& q_start, const VectorXd& v_start,
                                    const VectorXd& q, const VectorXd& v,
                                    bool check_targets) const {
  if (!self_contact_.empty()) {
    std::string failure = self_contact_.CheckStep(q);
    if (!failure.empty()) return failure;
  }
  if (target_contact_.empty() || !check_targets) return {};
  return target_contact_.CheckStep(q_start, v_start, q, v);
}

void SystemForces::UpdateHistories(State* state) {
  if (!target_contact_.empty()) {
    target_contact_.UpdateHistory(state->q, state->v, &state->contact_history);
    target_contact_.SetStepSize(0.0);
    target_contact_.ClearStep();
  }
  step_end_ = nullptr;
  if (!self_contact_.empty()) {
    self_contact_.ClearStep();
    self_contact_.UpdateHistory(state->q, state->v, &state->self_contact_history);
  }
  UpdateClearanceJointHistory(model_, state->q, state->v, state->body_rotation, joint_step_,
                              &state->joint_history);
  joint_step_ = 0.0;
}

}  // namespace ancfnet
