#pragma once
/// @file The generalised forces of the model's clearance joints and their Jacobians. The contact
/// force f and moments (m_J, m_B) of forces/clearance_contact.hpp act on the journal's and the
/// bearing's anchors (forces/joint_anchor.hpp) as
///   Q_J,b = A_bᵀ f + B_bᵀ m_J,   Q_B,b = −A_bᵀ f + B_bᵀ m_B,
/// Q = N(p)ᵀ f plus the rotational part, which enter M q̈ + Q_int = Q_ext as Q_int −= Q, and the
/// Jacobians are the chain rule through (c, ċ, ω) of both anchors plus their geometric stiffness
/// (docs/theory.md, "Clearance joints").

#include <vector>

#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/clearance_contact.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// What the journal does in its bearing (ClearanceJointState::mode).
enum class ClearanceMode {
  kFreeFlight = 0,  ///< δ ≤ 0: no contact
  kContact = 1,     ///< δ > 0 and |δ̇| ≤ v₀/10: the journal rides on the bearing
  kImpact = 2,      ///< δ > 0 and |δ̇| > v₀/10: an impact, still compressing or restituting
};

/// A joint at one state: its anchors and contact.
struct ClearanceJointState {
  AnchorMotion journal;
  AnchorMotion bearing;
  ClearanceContact contact;
  ClearanceMode mode = ClearanceMode::kFreeFlight;
};

/// Joint `j` of the model at (q, v), the bodies' reference rotations `rotation` and its history
/// (its v₀, ContactPairHistory::speed, and its LuGre bristle at the start of the step, advanced
/// over `step`; 0: the force at the state, for outputs). The mode compares |δ̇| with the stored
/// impact speed v₀ (at least the law's minimum approach speed).
ClearanceJointState CalcClearanceJointState(const Model& model, Index j, const VectorXd& q,
                                            const VectorXd& v,
                                            const std::vector<Matrix3d>& rotation,
                                            const ContactPairHistory& history,
                                            bool with_jacobian = false, double step = 0.0);

/// ws.internal_force −= Q and ws.viscous_force −= Q_dissipative of every joint, with the bodies'
/// rotations, the joints' histories and the step size (Workspace::joint_step) in ws.
void AddClearanceJointForces(const Model& model, const VectorXd& q, const VectorXd& v,
                             Workspace& ws);

/// Elastic energy stored in the joints at q, Σ ∫₀^δ F_elastic dδ (J), with the bodies' reference
/// rotations `rotation`.
double CalcClearanceJointEnergy(const Model& model, const VectorXd& q,
                                const std::vector<Matrix3d>& rotation);

/// matrix −= c_K ∂Q/∂q + c_C ∂Q/∂q̇ of every joint (SystemMatrix::AddClearanceJointBlock).
void AddClearanceJointJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                                const IterationWeights& weights, const Workspace& ws,
                                SystemMatrix* matrix);

/// After an accepted step of size `step` to (q, v), per joint as for contact pairs
/// (forces/impact_speed.hpp): apart, minus its closing speed; just touched, its impact speed;
/// touching, unchanged. The LuGre bristle of a touching joint is advanced over the step (in the
/// bearing's frame, ClearanceContact), that of a joint apart is zero.
void UpdateClearanceJointHistory(const Model& model, const VectorXd& q, const VectorXd& v,
                                 const std::vector<Matrix3d>& rotation, double step,
                                 std::vector<ContactPairHistory>* history);

}  // namespace ancfnet
