#pragma once
/// @file The one owner of a model's generalised forces and of their Jacobian, for every analysis:
///   R = M a + Q_int(q, v) − Q_ext(q),   ∂R = c_M M + c_C ∂Q/∂v + c_K ∂Q/∂q,
/// Q_int the elements' elastic and viscous forces, links, bodies and clearance joints
/// (forces/forces.hpp), the damping model (Rayleigh, modal), contact with targets and self-contact;
/// Q_ext the applied loads and gravity. Static analysis, the initial acceleration and the time
/// integrators (generalised-α, the midpoint rule, Verlet) take their forces from here, so that the
/// sum is written once, as Drake's FemModel::CalcResidual / CalcTangentMatrix are. Each step reads
/// top-down: FindContacts (detection), Calc / AssembleIterationMatrix (Newton), CheckStep (accept
/// or cut), UpdateHistories (after an accepted step).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/self_contact.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/solvers/damping_model.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

class SystemForces {
 public:
  /// `near_factor`: ContactCouplingSettings::near_factor of the self-contact pairs. The bodies'
  /// reference rotations that poses of targets carried by bodies are computed with are those in
  /// `ws` (Workspace::body_rotation), which must outlive this object. Without `with_damping` the
  /// model's Rayleigh and modal damping are left out (for analyses at rest).
  SystemForces(const Model& model, const Workspace& ws, double near_factor = 1.0,
               bool with_damping = true);

  bool has_contact() const { return !target_contact_.empty() || !self_contact_.empty(); }

  /// The contact pairs to watch during a step of size h from `state` (h = 0: the forces at the
  /// state itself): the self-contact candidates (SelfContact::FindCandidates). With
  /// `with_step_size`, h is also the step over which the LuGre law's bristles of target contact
  /// and of the clearance joints are advanced (TargetContact::SetStepSize,
  /// Workspace::joint_step).
  void FindContacts(const State& state, double h, bool with_step_size);
  /// After FindContacts: the owner pairs of the iteration matrix's contact couplings a step of
  /// size h from (q, v) needs (the coupled self-contact pairs, the probes near targets carried
  /// by bodies) into *required, and those worth keeping into *near
  /// (SystemMatrix::UpdateContactCouplings).
  void FindCouplings(const VectorXd& q, const VectorXd& v, double h, const SystemMatrix& matrix,
                     std::vector<std::pair<Index, Index>>* required,
                     std::vector<std::pair<Index, Index>>* near);

  /// For the midpoint rule, from now until UpdateHistories: the step from (q_start, v_start) to
  /// *q_end (kept up to date by the caller through the Newton iterations), over which the
  /// elements' and contacts' elastic forces are discrete gradients (BeginStepForceCorrections,
  /// TargetContact::SetStep, SelfContact::SetStep). nullptr ends it.
  void SetStep(const VectorXd& q_start, const VectorXd& v_start, const VectorXd* q_end,
               Workspace& ws);

  /// All forces at (q, v) into ws: ws.internal_force and ws.viscous_force (elements, links,
  /// bodies, clearance joints, their step corrections after SetStep, damping, contact),
  /// ws.contact_energy, ws.applied_force and ws.external_force at the load factor λ (1 in
  /// dynamics). `history` is each target-contact pair's at the start of the step.
  void Calc(const VectorXd& q, const VectorXd& v, const std::vector<ContactPairHistory>& history,
            double load_factor, Workspace& ws) const;
  /// matrix = c_M M + c_C ∂Q/∂v + c_K ∂Q/∂q at (q, v) of the same forces (the dense modal
  /// damping left out: DampingModel::AddRayleighJacobian), restricted to the matrix's unknowns.
  /// The forces it leaves in ws are not all of them: take those from Calc.
  void AssembleIterationMatrix(const VectorXd& q, const VectorXd& v,
                               const std::vector<ContactPairHistory>& history,
                               const IterationWeights& weights, double load_factor, Workspace& ws,
                               SystemMatrix* matrix) const;

  /// Empty when a converged step from (q_start, v_start) to (q, v) may be accepted, else why not:
  /// SelfContact::CheckStep, then, with `check_targets`, TargetContact::CheckStep.
  std::string CheckStep(const VectorXd& q_start, const VectorXd& v_start, const VectorXd& q,
                        const VectorXd& v, bool check_targets) const;
  /// After an accepted step to *state: the contact histories of its target-contact and
  /// self-contact pairs and of the clearance joints (the bristles advanced over the step); the
  /// step of SetStep ended, and target contact's forces from now on those at a state (step size
  /// 0).
  void UpdateHistories(State* state);

 private:
  const Model& model_;
  std::optional<DampingModel> damping_;
  TargetContact target_contact_;
  SelfContact self_contact_;
  std::vector<std::pair<Index, Index>> body_couplings_;  // probes near targets on bodies
  const VectorXd* step_end_ = nullptr;                   // SetStep
  double joint_step_ = 0.0;  // FindContacts: h of the clearance joints' bristles (Workspace)
};

}  // namespace ancfnet
