#pragma once
/// @file Explicit velocity Verlet (kick–drift–kick) with the constant mass matrix factorised
/// once; for comparison with generalised-α. Conditionally stable: h < 2/ω_max.

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/integrators/step_outcome.hpp"
#include "ancfnet/solvers/linear_solver.hpp"
#include "ancfnet/solvers/system_forces.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

class ExplicitVerletIntegrator {
 public:
  /// Throws InputError for a model whose contact friction is the LuGre law: its stiff bristle
  /// (natural frequency √(σ₀ g) for a block) needs the implicit integrators.
  explicit ExplicitVerletIntegrator(const Model& model);

  /// Factorises the mass matrix and sets a₀ = M⁻¹ (Q_ext − Q_int) with the state's broken links;
  /// estimates the critical step at the state (EstimateCriticalStep), which the message of a
  /// step that diverges quotes. False if M is singular.
  bool Initialize(State* state);
  /// Writes the stability estimate of the last Initialize (all else a step needs is the state).
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Continues from `state` (instead of Initialize): the mass matrix factorised, the state's
  /// acceleration kept, the stability estimate read. False if M is singular.
  bool Resume(const State& state, ArchiveReader* in);
  /// v_{n+½} = v_n + h/2 a_n; q_{n+1} = q_n + h v_{n+½};
  /// a_{n+1} = M⁻¹ (Q_ext − Q_int)(q_{n+1}, v_{n+½}); v_{n+1} = v_{n+½} + h/2 a_{n+1}
  /// (Hairer, Lubich & Wanner 2006, I.1.4; velocity-dependent forces use v_{n+½}).
  /// Rejected, with the state unchanged, when the result is not finite; the failure then says
  /// whether h is above the critical step estimated at the last Initialize (and at which time),
  /// or below it, so that a stiffer force or a runaway motion made the run diverge. (Estimated at
  /// the last accepted state instead, which had often grown wild before it overflowed, the
  /// "limit" came out as 10⁻¹⁰⁴ s.)
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
  Workspace ws_;
  SystemForces forces_;
  std::vector<ContactPairHistory> contact_history_;  // the state's, at the start of the step
  DofMap dofs_;
  SparseLinearSolver mass_solver_;
  VectorXd net_force_;  // Q_ext − Q_int, all coordinates
  VectorXd rhs_;
  VectorXd a_free_;
  State previous_;
  double critical_step_ = 0.0;       // EstimateCriticalStep at the last Initialize (s) ...
  double critical_step_time_ = 0.0;  // ... at this time (s)
};

}  // namespace ancfnet
