#pragma once
/// @file Explicit velocity Verlet (kick–drift–kick) with the constant mass matrix factorised
/// once; for comparison with generalised-α. Conditionally stable: h < 2/ω_max.

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/self_contact.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/step_outcome.hpp"
#include "ancfnet/solvers/damping_model.hpp"
#include "ancfnet/solvers/linear_solver.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

class ExplicitVerletIntegrator {
 public:
  /// Throws InputError for a model whose contact friction is the LuGre law: its stiff bristle
  /// (natural frequency √(σ₀ g) for a block) needs the implicit integrators.
  explicit ExplicitVerletIntegrator(const Model& model);

  /// Factorises the mass matrix and sets a₀ = M⁻¹ (Q_ext − Q_int) with the state's broken links.
  /// False if M is singular.
  bool Initialize(State* state);
  /// Nothing beyond the state is carried from step to step.
  void SaveCheckpoint(ArchiveWriter*) const {}
  /// Continues from `state` (instead of Initialize): the mass matrix factorised, the state's
  /// acceleration kept. False if M is singular.
  bool Resume(const State& state, ArchiveReader*) { return Prepare(state); }
  /// v_{n+½} = v_n + h/2 a_n; q_{n+1} = q_n + h v_{n+½};
  /// a_{n+1} = M⁻¹ (Q_ext − Q_int)(q_{n+1}, v_{n+½}); v_{n+1} = v_{n+½} + h/2 a_{n+1}
  /// (Hairer, Lubich & Wanner 2006, I.1.4; velocity-dependent forces use v_{n+½}).
  /// Rejected, with the state unchanged, when the result is not finite.
  StepOutcome Step(double h, State* state);
  const Workspace& workspace() const { return ws_; }
  static constexpr EnergyQuadrature kEnergyQuadrature = EnergyQuadrature::kTrapezoidal;
  /// Largest stable step 2/ω_max for small motions about the configuration q (s), with ω_max
  /// bounded from above by the largest element frequency (Irons & Treharne 1971), so the
  /// estimate is on the safe side.
  double EstimateCriticalStep(const VectorXd& q) const;

 private:
  // Takes over the state's broken links, body rotations and histories and factorises M.
  bool Prepare(const State& state);
  void CalcAcceleration(const VectorXd& q, const VectorXd& v, VectorXd* a);

  const Model& model_;
  DampingModel damping_;
  TargetContact contact_;
  SelfContact self_contact_;
  std::vector<ContactPairHistory> contact_history_;  // the state's, at the start of the step
  Workspace ws_;
  DofMap dofs_;
  SparseLinearSolver mass_solver_;
  VectorXd net_force_;  // Q_ext − Q_int, all coordinates
  VectorXd rhs_;
  VectorXd a_free_;
  State previous_;
};

}  // namespace ancfnet
