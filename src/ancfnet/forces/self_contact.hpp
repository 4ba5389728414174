#pragma once
/// @file Self-contact of a model's threads and knots: capsules along the elements' deformed
/// centre lines (or inspection spheres) and point-mass spheres touching each other. Each step
/// starts with a broad phase (uniform grid) and a narrow phase that keep the pairs within a
/// speculative search margin; the Newton iterations then evaluate only those. The force of a
/// pair acts at the closest points of the two axes, at material coordinates p, and is mapped to
/// positions and slopes by Q = S(p)ᵀ f with S(p) the chord's interpolation of the shape functions
/// (docs/theory.md, "Self-contact").

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "ancfnet/contact/broad_phase/uniform_grid.hpp"
#include "ancfnet/contact/contact_pair_force.hpp"
#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/contact/distance/segment_segment.hpp"
#include "ancfnet/contact/self_pair_jacobian.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/self_contact_primitives.hpp"
#include "ancfnet/model/capsule_axis.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

class SelfContact {
 public:
  /// `near_factor` ≥ 1: the slack s of near_owners() (ContactCouplingSettings::near_factor).
  explicit SelfContact(const Model& model, double near_factor = 1.0);
  bool empty() const { return primitives_.empty(); }
  const std::vector<SelfContactPrimitive>& primitives() const { return primitives_; }

  /// At the state that starts a step of size h: the pairs, not excluded, whose gap is below the
  /// sum of their search margins m = 2 h max |ẋ| + r/2 (each end's speed, the primitive's
  /// radius), with the history of each. Among them, the coupled pairs, whose gap is below
  /// g_c = (r_a + r_b)/4 + 2 h max(−u·(ẋ_a − ẋ_b), 0) (touching, nearly touching, or closing
  /// that gap within the step), and the near pairs, whose gap is below s g_c (docs/theory.md,
  /// "Self-contact"). h is also the step over which the LuGre law's bristles are advanced
  /// (TargetContact::SetStepSize; 0: the forces at the state, for outputs). Allocates only while
  /// its storage grows.
  void FindCandidates(const State& state, double h);
  /// Owners (SystemMatrix::UpdateContactCouplings) of the coupled pairs.
  const std::vector<std::pair<Index, Index>>& coupled_owners() const { return coupled_owners_; }
  /// Owners of the near pairs (the coupled ones among them): the couplings worth keeping.
  const std::vector<std::pair<Index, Index>>& near_owners() const { return near_owners_; }
  /// Number of candidate pairs.
  int num_candidates() const { return static_cast<int>(candidates_.size()); }

  /// After FindCandidates at q_start: the step from there to *q_end (kept up to date by the
  /// caller through the Newton iterations) whose midpoint forces AddForces is asked for. From
  /// then on the elastic force of each candidate pair is the discrete gradient over the step
  /// (CalcElasticStepForce) and ws.contact_energy is that at q_end, as in TargetContact::SetStep.
  /// Both must outlive the calls; ClearStep ends it.
  void SetStep(const VectorXd& q_start, const VectorXd* q_end) {
    step_start_ = &q_start;
    step_end_ = q_end;
  }
  void ClearStep() { step_end_ = nullptr; }

  /// ws.internal_force −= Qᵀ f, ws.viscous_force alike, ws.contact_energy += Σ ∫ F_el dδ over
  /// the touching candidate pairs at (q, v). After SetStep, (q, v) is the step's midpoint and
  /// the pairs touching at either end of the step count too.
  void AddForces(const VectorXd& q, const VectorXd& v, Workspace& ws) const;
  /// matrix += c_K ∂Q/∂q + c_C ∂Q/∂q̇ of the touching candidates (after SetStep also those
  /// touching at either end of the step only, whose discrete gradient acts), complete
  /// (CalcSelfPairJacobian: the closest points moving with the coordinates, friction's tangent
  /// plane turning; in a step, the turning of the discrete gradient's direction left out): into
  /// the contact coupling of a coupled pair (coupled_owners() must have been added to `matrix`),
  /// and for the others (or without the coupling) only the blocks of each primitive with itself, or
  /// all of them when both lie on one element (a quasi-Newton matrix for a pair that was apart at
  /// the step start; the residual stays exact).
  void AddJacobian(const VectorXd& q, const VectorXd& v, const IterationWeights& weights,
                   SystemMatrix* matrix) const;
  /// Empty when the step to q may be accepted; else why not: a primitive moved farther than its
  /// search margin (a pair not searched might touch), a pair's closest-point direction
  /// reversed (the two passed through each other), or a pair overlaps by more than half its
  /// mean radius (the step was too long to resolve the impact, or the law is too soft).
  std::string CheckStep(const VectorXd& q) const;
  /// After an accepted step: the history of the candidate pairs at (q, v), as
  /// TargetContact::UpdateHistory does it per pair (bristles included).
  void UpdateHistory(const VectorXd& q, const VectorXd& v,
                     std::vector<SelfContactPairHistory>* history) const;

  /// Appends a record of every touching candidate pair at (q, v) (after FindCandidates at that
  /// state): the force on primitive a at its material coordinate, the point on b's surface,
  /// target −1.
  void CollectContacts(const VectorXd& q, const VectorXd& v, std::vector<ContactPoint>* out) const;
  /// Touching pairs, total normal force (N) and largest penetration (m) at (q, v).
  struct Summary {
    int active = 0;
    double normal_force = 0.0;
    double max_penetration = 0.0;
  };
  Summary Summarize(const VectorXd& q, const VectorXd& v) const;

 private:
  struct Candidate {
    int a = 0, b = 0;                              // primitives, a < b
    ContactPairHistory history;                    // at the start of the step
    Vector3d direction_start = Vector3d::UnitZ();  // closest-point direction at the step start
    bool coupled = false;                          // gap < g_c at the step start
    double penetration_start = 0.0;                // Penetration() at the step start
  };
  // Axis ends of a primitive and their velocities (LocateCapsuleAxis).
  using Axis = CapsuleAxis;
  // One pair: closest-point parameters on each axis, the gap, the direction u from b's closest
  // point to a's, their relative velocity, and the force on a.
  struct PairState {
    double s = 0.0, t = 0.0, gap = 0.0;
    bool counted = true;  // the pair's closest points are not counted by a neighbour
    // CalcStepPair: the discrete gradient over the step acts (the pair touches at its start or
    // end), whether or not it touches at the midpoint.
    bool step_force = false;
    Vector3d direction = Vector3d::UnitZ();
    Vector3d velocity = Vector3d::Zero();
    ContactPairForce force;
    // For the Jacobian (PairDetail::kJacobian): each side's axis and closest point, x_a − x_b.
    SelfPairSide side_a, side_b;
    Vector3d separation = Vector3d::Zero();
  };
  enum class PairDetail { kGeometry, kForce, kJacobian };
  // Whether a closest point at `part` of capsule p, seen in `direction` (from the other body
  // towards p), is counted by p rather than by its neighbour along the chain.
  bool OwnsClosestPoint(const SelfContactPrimitive& p, SegmentPart part, const Vector3d& direction,
                        const VectorXd& q) const;
  PairState CalcPair(const Candidate& c, const VectorXd& q, const VectorXd& v,
                     PairDetail detail) const;
  // A pair's penetration as its stored energy sees it: −gap, or at most 0 where a neighbour
  // counts its closest points.
  static double Penetration(const PairState& pair) {
    return pair.counted ? -pair.gap : std::min(-pair.gap, 0.0);
  }
  // After SetStep: the pair's force at the midpoint (q, v) with its elastic part the discrete
  // gradient over the step; its energy at the end of the step is added to *energy. With
  // `jacobian`, the derivatives too (2 ∂F̄/∂δ₁ in place of the elastic slope).
  PairState CalcStepPair(const Candidate& c, const VectorXd& q, const VectorXd& v, bool jacobian,
                         double* energy) const;
  // ws −= f on a's blocks and += f on b's, at the pair's closest points.
  void ApplyPairForce(const Candidate& c, const PairState& pair, Workspace& ws) const;
  // Weights of a primitive's blocks at axis parameter s (4 for an element, 1 for a point mass)
  // and the blocks' first coordinates.
  int Blocks(const SelfContactPrimitive& p, double s, std::array<double, 4>* weight,
             std::array<Index, 4>* dof) const;
  // matrix += the Jacobian's blocks of primitive p (rows and columns from `first`, 0 or 12) with
  // itself, on its element's or point mass's own blocks.
  void AddOwnBlocks(const SelfContactPrimitive& p, const Matrix24d& jacobian, int first,
                    SystemMatrix* matrix) const;

  const Model& model_;
  std::vector<SelfContactPrimitive> primitives_;
  SelfContactFilter filter_;
  UniformGridBroadPhase broad_phase_;
  // Storage of FindCandidates.
  std::vector<Aabb> boxes_;
  std::vector<double> margin_;
  std::vector<Vector3d> start_x0_, start_x1_;
  std::vector<std::pair<int, int>> overlaps_;
  std::vector<Candidate> candidates_;
  std::vector<std::pair<Index, Index>> coupled_owners_;
  double step_ = 0.0;  // h of FindCandidates
  std::vector<std::pair<Index, Index>> near_owners_;
  double near_factor_ = 1.0;
  const VectorXd* step_start_ = nullptr;  // SetStep
  const VectorXd* step_end_ = nullptr;
};

}  // namespace ancfnet
