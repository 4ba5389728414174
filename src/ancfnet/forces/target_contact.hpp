#pragma once
/// @file Contact forces between the model (cable inspection spheres or capsule chains,
/// point-mass spheres) and its rigid targets (contact/contact_spec.hpp): a normal law on the
/// penetration δ and its rate, regularised friction on the tangential slip, applied at the
/// probe's point nearest the target and mapped to positions and slopes by Q = Sᵀ f, with the
/// Jacobians an implicit integrator needs (docs/theory.md, "Contact with rigid targets" and
/// "Capsule chains against rigid targets").

#include <optional>
#include <string>
#include <vector>

#include "ancfnet/contact/contact_pair_force.hpp"
#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/contact/segment_distance_bound.hpp"
#include "ancfnet/contact/target_distance.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/target_pair_jacobian.hpp"
#include "ancfnet/model/capsule_axis.hpp"
#include "ancfnet/model/contact_probes.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

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

  /// The step from q_start to *q_end (which the caller keeps up to date through the Newton
  /// iterations) whose midpoint forces AddForces is asked for: from now on it gives each pair's
  /// elastic force as the discrete gradient over the step (CalcElasticStepForce), so that its
  /// work equals the change of the contact energy exactly, and ws.contact_energy that at q_end.
  /// Finds the pairs' penetrations at q_start. Both must outlive the calls; ClearStep ends it.
  void SetStep(const VectorXd& q_start, const VectorXd& v_start, const VectorXd* q_end);
  void ClearStep() { step_end_ = nullptr; }

  /// ws.internal_force −= Sᵀ f and ws.viscous_force −= Sᵀ f_dissipative for every touching pair
  /// (and += Gᵀ f on the body carrying the target, G its point-velocity map at the contact point),
  /// S = (1 − t*) S(ξ₀) + t* S(ξ₁) at the probe's point c(t*) deepest in the target;
  /// ws.contact_energy = Σ ∫ F_elastic dδ. `history` is each pair's at the start of the step.
  /// After SetStep: (q, v) is the step's midpoint and the elastic part of f is the discrete
  /// gradient between the step's ends, for every pair touching at either end or at (q, v).
  void AddForces(const VectorXd& q, const VectorXd& v,
                 const std::vector<ContactPairHistory>& history, Workspace& ws) const;
  /// matrix += c_K ∂Q/∂q + c_C ∂Q/∂q̇ of the contact forces, complete (CalcTargetPairJacobian:
  /// the tangent plane turning, t* of a capsule at an interior smooth minimum moving with the
  /// element's coordinates and the body's pose, the slip and the reaction's moment arm varying
  /// with the pose; docs/theory.md, "Complete contact Jacobians"). A probe without a coupling to
  /// the body (FindBodyCouplings) adds its own blocks and the body's, not those between them.
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
  /// forces are those AddForces applies (force_W = F n + f_t on the probe); ξ is that of c(t*),
  /// (1 − t*) ξ₀ + t* ξ₁. For outputs: it allocates as `out` grows.
  void CollectContacts(const VectorXd& q, const VectorXd& v,
                       const std::vector<ContactPairHistory>& history,
                       std::vector<ContactPoint>* out) const;

 private:
  // One pair's force (contact/contact_pair_force.hpp) and where it acts.
  struct PairForce : ContactPairForce {
    Index target = -1;
    double t = 0.0;                             // t* of the probe's point on its axis
    Vector3d surface_point = Vector3d::Zero();  // closest point of the target's surface (m)
    Vector3d normal = Vector3d::UnitZ();        // outward normal of the target
    TargetPairGeometry geometry;                // for the Jacobian (with_jacobian only)
  };
  // Where target t is: fixed, or moving with its body; and the world centre of its bounding ball.
  struct Frame {
    Index body = -1;
    BodyPose pose;
    BodyVelocity velocity;
    Vector3d bound_center = Vector3d::Zero();
    double bound_radius = 0.0;
  };
  Frame CalcFrame(std::size_t t, const VectorXd& q, const VectorXd& v) const;
  // A probe's axis: its end points and their velocities (equal ends for a sphere;
  // LocateCapsuleAxis).
  using Axis = CapsuleAxis;
  // The point c(t*) of a probe's axis deepest in a target, its velocity and its distance to the
  // target's surface (in world coordinates).
  struct ProbePoint {
    double t = 0.0;
    Vector3d x, x_dot;
    Vector3d axis, axis_rate;  // x₁ − x₀ and its rate
    TargetDistance distance;
    double distance_lower_bound = 0.0;  // SegmentTargetDistance::lower_bound (m)
  };
  ProbePoint FindProbePoint(const ContactTarget& target, const Frame& frame,
                            const Axis& axis) const;
  // A probe's axis ends in its target's frame (the world's for a fixed target).
  struct TargetAxis {
    Vector3d x0, x1;
  };
  static TargetAxis InTargetFrame(const Frame& frame, const Axis& axis);
  // FindProbePoint with the axis' ends in the target's frame already found.
  ProbePoint FindProbePoint(const ContactTarget& target, const Frame& frame, const Axis& axis,
                            const TargetAxis& ends) const;
  // FindProbePoint for the (probe, target) pair `pair`, or nothing when the target's bounding
  // ball or the pair's distance bound (distance_bounds_) shows it farther than `reach` (m) from
  // the target; updates the bound.
  std::optional<ProbePoint> FindProbePointWithin(std::size_t pair, const ContactTarget& target,
                                                 const Frame& frame, const Axis& axis,
                                                 double reach) const;
  // Centre-line boxes of the elements, found once per element in a loop over the probes.
  class ElementBoxes;
  // False where the box of the probe's element (at the positions `boxes` is for) is farther from
  // the target's ball in `frame` than the probe's radius: no probe of that element can touch.
  static bool MayReach(const ContactProbe& probe, ElementBoxes& boxes, const Frame& frame);
  // False where the target's bounding ball shows the axis farther from the target than
  // reach + lead × (the largest speed of the axis relative to the target's surface): a
  // conservative FindBodyCouplings test without the distance query.
  static bool MayCouple(const Frame& frame, const Axis& axis, double reach, double lead);
  // Penetration, normal, ∂n/∂x and the probe's velocity relative to the target's surface.
  ContactKinematics CalcKinematics(const Frame& frame, const ContactProbe& probe,
                                   const ProbePoint& point) const;
  PairForce CalcPairForce(const Frame& frame, const ContactProbe& probe, const ProbePoint& point,
                          const ContactPairHistory& history, bool with_jacobian) const;
  // Owner of a probe's blocks in SystemMatrix contact couplings.
  Index ProbeOwner(const ContactProbe& probe) const;
  // Adds a pair's force to ws (probe and body), as AddForces describes.
  void ApplyPairForce(const ContactProbe& probe, const PairForce& f, Workspace& ws) const;
  // Adds a pair's Jacobian blocks to the matrix, as AddJacobian describes.
  void AddPairJacobian(const ContactProbe& probe, const PairForce& f,
                       const IterationWeights& weights, SystemMatrix* matrix) const;
  // AddForces and AddJacobian after SetStep: midpoint forces with discrete-gradient elastic
  // parts, and their derivatives.
  void AddStepForces(const VectorXd& q, const VectorXd& v,
                     const std::vector<ContactPairHistory>& history, Workspace& ws) const;
  void AddStepJacobian(const VectorXd& q, const VectorXd& v,
                       const std::vector<ContactPairHistory>& history,
                       const IterationWeights& weights, SystemMatrix* matrix) const;
  // The targets' frames at the midpoint (q, v) and at the end of the step.
  void BeginStepEvaluation(const VectorXd& q, const VectorXd& v) const;
  // After SetStep and BeginStepEvaluation: the force of pair (probe p, target t) at the
  // midpoint, its elastic part the discrete gradient over the step; with_jacobian, its
  // derivatives with 2 ∂F̄/∂δ₁ in place of the elastic slope at the midpoint (the end moves twice
  // as far). Nothing when the pair touches at neither end nor at the midpoint. Adds Φ(δ₁) to
  // *energy.
  std::optional<PairForce> CalcStepPairForce(std::size_t p, std::size_t t, const Axis& axis,
                                             const Axis& end_axis,
                                             const ContactPairHistory& history,
                                             bool with_jacobian, double* energy) const;
  // Calls visit(probe, force) for every pair with a force in the midpoint rule's step
  // (CalcStepPairForce) at (q, v), skipping the elements whose boxes show them out of reach.
  template <class Visit>
  void ForEachStepPair(const VectorXd& q, const VectorXd& v,
                       const std::vector<ContactPairHistory>& history, bool with_jacobian,
                       double* energy, Visit&& visit) const;
  // ∂F/∂δ of the normal law's elastic part at penetration δ (N/m).
  double ElasticSlope(double penetration) const;
  // The displacement over the step of a pair's contact point relative to its target, as the
  // forces at the midpoint see it: S Δy − G Δp (Q·Δq = f·d for the force f at that point).
  Vector3d CalcStepDisplacement(const ContactProbe& probe, const PairForce& f) const;
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
  std::vector<TargetBoundingSphere> bounding_spheres_;  // per target, in its own frame
  mutable std::vector<Frame> frames_;  // per target, at the (q, v) being evaluated
  // Per (probe, target) pair: where it was when its distance was last found, to skip the
  // distance queries of pairs that cannot touch (SegmentDistanceBound).
  mutable std::vector<SegmentDistanceBound> distance_bounds_;
  // SetStep: the step's ends, and each pair's penetration at the start (−∞: farther than its
  // probe's radius, found exactly when the pair touches at the end).
  const VectorXd* step_start_ = nullptr;
  const VectorXd* step_start_velocity_ = nullptr;
  const VectorXd* step_end_ = nullptr;
  mutable std::vector<double> start_penetration_;
  mutable std::vector<Frame> end_frames_;
};

}  // namespace ancfnet
