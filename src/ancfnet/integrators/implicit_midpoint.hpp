#pragma once
/// @file Implicit midpoint rule for M q̈ + Q_int(q, q̇) = Q_ext(q, t): the forces are taken at
/// the middle of the step,
///   q_{n+1} = q_n + h v_{n+½},   M (v_{n+1} − v_n) / h = (Q_ext − Q_int)(q_{n+½}, v_{n+½}),
/// with q_{n+½} = (q_n + q_{n+1})/2, v_{n+½} = (v_n + v_{n+1})/2 (Hairer, Lubich & Wanner 2006,
/// I.1.2 and IV.2). Second order, symplectic, without numerical damping; it keeps every
/// quadratic invariant, so linear and angular momentum Σ q_i × (M q̇)_i are conserved to the
/// Newton tolerance whenever the internal forces are invariant under rigid rotation
/// (docs/theory.md, "Implicit midpoint rule"). The contact forces' elastic parts are discrete
/// gradients over the step (Gonzalez 1996), so that their work equals the change of the contact
/// energy and the energy balance holds through impacts to the Newton tolerance
/// (docs/theory.md, "Energy-consistent contact").

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/integrators/implicit_step_core.hpp"
#include "ancfnet/integrators/step_outcome.hpp"

namespace ancfnet {

class ImplicitMidpointIntegrator {
 public:
  ImplicitMidpointIntegrator(const Model& model, const DynamicSettings& settings);

  /// Sets the consistent initial acceleration a₀ = M⁻¹ (Q_ext − Q_int)(q₀, v₀) (reported only;
  /// the scheme itself does not need it). Returns false when the mass matrix is singular. Called
  /// again after a failure: the state's broken links are taken over.
  bool Initialize(State* state);
  /// Writes what the next steps depend on besides the state (ImplicitStepCore's).
  void SaveCheckpoint(ArchiveWriter* out) const { core_.SaveCheckpoint(out); }
  /// Continues from `state` with what SaveCheckpoint wrote (instead of Initialize). Always true;
  /// throws InputError when `in` does not fit.
  bool Resume(const State& state, ArchiveReader* in) {
    core_.Resume(state, in);
    midpoint_ = state;
    return true;
  }
  /// Advances `state` by h; state->a becomes the step's mean acceleration (v_{n+1} − v_n)/h.
  /// On rejection the state is left unchanged.
  StepOutcome Step(double h, State* state);
  /// Forces at the middle of the last accepted step (for energy accounting).
  const Workspace& workspace() const { return core_.workspace(); }
  static constexpr EnergyQuadrature kEnergyQuadrature = EnergyQuadrature::kMidpoint;

  /// Newton problem of one step; its unknown is the free part of the mean acceleration.
  class StepProblem;

 private:
  ImplicitStepCore core_;
  State midpoint_;  // q_{n+½}, v_{n+½} at the current Newton iterate
  VectorXd end_;    // q_{n+1} = 2 q_{n+½} − q_n at that iterate (ImplicitStepCore::SetStepEnd)
};

}  // namespace ancfnet
