#pragma once
/// @file Contact forces between the model (cable inspection spheres, point-mass spheres) and its
/// rigid targets (model/contact_spec.hpp): a normal law on the penetration δ and its rate,
/// regularised friction on the tangential slip, applied at the inspection point's material
/// coordinate and mapped to positions and slopes by Q = Sᵀ(ξ) f, with the Jacobians an implicit
/// integrator needs (docs/theory.md, "Contact with rigid targets").

#include <string>
#include <vector>

#include "ancfnet/assembly/forces.hpp"
#include "ancfnet/contact/contact_pair_force.hpp"
#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// An inspection sphere: a material point of a cable element, or a point mass.
struct ContactProbe {
  Index element = -1;                 ///< cable element, or −1 for a point mass
  Index point_mass = -1;              ///< point mass, or −1
  double xi = 0.0;                    ///< ξ ∈ (0, 1) on the element
  Vector4d shape = Vector4d::Zero();  ///< S₁ … S₄ at ξ (r = Σ S_k e_k)
  double radius = 0.0;                ///< m
};

/// The inspection spheres of the model in order: for each cable element its points at
/// ξ = (j + ½)/n, then one per point mass. Empty without contact targets.
std::vector<ContactProbe> MakeContactProbes(const Model& model);

/// Number of (probe, target) pairs: the size of State::contact_history.
Index CountContactPairs(const Model& model);

class TargetContact {
 public:
  explicit TargetContact(const Model& model);
  bool empty() const { return probes_.empty(); }
  /// The bodies' reference rotations (State::body_rotation) that the poses of targets carried by
  /// bodies are computed with, R_WB = R_ref exp(ψ̃); it must outlive the calls. Unset: the
  /// bodies' initial orientations.
  void SetBodyRotations(const std::vector<Matrix3d>* rotations) { body_rotation_ = rotations; }
  /// The size h (s) of the step being taken, over which the LuGre law's bristles are advanced
  /// (ContactPairHistory::bristle → its end-of-step value) in AddForces, AddJacobian and
  /// UpdateHistory. 0 (the default): the forces at the state with the history as it is, for
  /// outputs.
  void SetStepSize(double h) { step_ = h; }
  /// Owner pairs (SystemMatrix::AddContactCouplings) of the probes within reach of a target
  /// carried by a body during a step of size h from (q, v): gap < r + 2 h |ẋ_rel| + r/2. Their
  /// Jacobian blocks that couple the probe and the body go into those couplings (a pair not
  /// found gets its probe's block only).
  void FindBodyCouplings(const VectorXd& q, const VectorXd& v, double h, const SystemMatrix& matrix,
                         std::vector<std::pair<Index, Index>>* owners) const;

  /// ws.internal_force −= Sᵀ f and ws.viscous_force −= Sᵀ f_dissipative for every touching pair
  /// (and += Gᵀ f on the body carrying the target, G its point-velocity map at the contact point);
  /// ws.contact_energy = Σ ∫ F_elastic dδ. `history` is each pair's at the start of the step.
  void AddForces(const VectorXd& q, const VectorXd& v,
                 const std::vector<ContactPairHistory>& history, Workspace& ws) const;
  /// matrix += c_K ∂Q/∂q + c_C ∂Q/∂q̇ of the contact forces. Left out: the friction force's
  /// dependence on the positions through the tangent plane.
  void AddJacobian(const VectorXd& q, const VectorXd& v,
                   const std::vector<ContactPairHistory>& history, const IterationWeights& weights,
                   SystemMatrix* matrix) const;
  /// Empty when a converged step from (q_start, v_start) to (q, v) may be accepted, else why not:
  /// a probe sank into a target by more than ContactSpec::penetration_increment of its radius
  /// during the step (δ − max(δ_start, 0) > η r).
  std::string CheckStep(const VectorXd& q_start, const VectorXd& v_start, const VectorXd& q,
                        const VectorXd& v) const;
  /// After an accepted step: a pair apart stores minus its closing speed; a pair that has just
  /// touched freezes its impact speed (the larger of the closing speeds before and now, at least
  /// the law's minimum); a pair in contact keeps it. The LuGre bristle of a touching pair is
  /// advanced over the step (SetStepSize), that of a pair apart is zero.
  void UpdateHistory(const VectorXd& q, const VectorXd& v,
                     std::vector<ContactPairHistory>* history) const;

  /// Number of touching pairs, total normal force (N) and largest penetration (m) at (q, v).
  struct Summary {
    int active = 0;
    double normal_force = 0.0;
    double max_penetration = 0.0;
  };
  Summary Summarize(const VectorXd& q, const VectorXd& v,
                    const std::vector<ContactPairHistory>& history) const;

  /// Appends a record of every touching (probe, target) pair at (q, v) to `out`, probes in the
  /// order of MakeContactProbes and, for each, targets in the order of ContactSpec::targets. The
  /// forces are those AddForces applies (force_W = F n + f_t on the probe). For outputs: it
  /// allocates as `out` grows.
  void CollectContacts(const VectorXd& q, const VectorXd& v,
                       const std::vector<ContactPairHistory>& history,
                       std::vector<ContactPoint>* out) const;

 private:
  // One pair's force (contact/contact_pair_force.hpp) and where it acts.
  struct PairForce : ContactPairForce {
    Index target = -1;
    Vector3d surface_point = Vector3d::Zero();  // closest point of the target's surface (m)
    Vector3d normal = Vector3d::UnitZ();        // outward normal of the target
  };
  // Where a target is: fixed, or moving with its body.
  struct Frame {
    Index body = -1;
    BodyPose pose;
    BodyVelocity velocity;
  };
  Frame CalcFrame(const ContactTarget& target, const VectorXd& q, const VectorXd& v) const;
  // Penetration, normal, ∂n/∂x and the probe's velocity relative to the target's surface.
  ContactKinematics CalcKinematics(const ContactTarget& target, const Frame& frame,
                                   const ContactProbe& probe, const Vector3d& x,
                                   const Vector3d& x_dot) const;
  PairForce CalcPairForce(const ContactTarget& target, const Frame& frame,
                          const ContactProbe& probe, const Vector3d& x, const Vector3d& x_dot,
                          const ContactPairHistory& history, bool with_jacobian) const;
  // Owner of a probe's blocks in SystemMatrix contact couplings.
  Index ProbeOwner(const ContactProbe& probe) const;
  void Locate(const ContactProbe& probe, const VectorXd& q, const VectorXd& v, Vector3d* x,
              Vector3d* x_dot) const;
  // Calls visit(probe, force) for every touching (probe, target) pair at (q, v); force.target is
  // the target's index.
  template <class Visit>
  void ForEachTouchingPair(const VectorXd& q, const VectorXd& v,
                           const std::vector<ContactPairHistory>& history, bool with_jacobian,
                           Visit&& visit) const;

  const Model& model_;
  std::vector<ContactProbe> probes_;
  const std::vector<Matrix3d>* body_rotation_ = nullptr;
  double step_ = 0.0;
  mutable std::vector<Frame> frames_;  // per target, at the (q, v) being evaluated
};

}  // namespace ancfnet
