#pragma once
/// @file Explicit velocity Verlet (kick–drift–kick) with the constant mass matrix factorised
/// once; for comparison with generalised-α. Conditionally stable: h ≲ L_e / √(EA/ρA).

#include "ancfnet/assembly/forces.hpp"
#include "ancfnet/integrators/step_outcome.hpp"
#include "ancfnet/solvers/linear_solver.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

class ExplicitVerletIntegrator {
 public:
  explicit ExplicitVerletIntegrator(const Model& model);

  /// Factorises the mass matrix and sets a₀ = M⁻¹ (Q_ext − Q_int). False if M is singular.
  bool Initialize(State* state);
  /// v_{n+½} = v_n + h/2 a_n; q_{n+1} = q_n + h v_{n+½};
  /// a_{n+1} = M⁻¹ (Q_ext − Q_int)(q_{n+1}, v_{n+½}); v_{n+1} = v_{n+½} + h/2 a_{n+1}
  /// (Hairer, Lubich & Wanner 2006, I.1.4; velocity-dependent forces use v_{n+½}).
  /// Rejected, with the state unchanged, when the result is not finite.
  StepOutcome Step(double h, State* state);
  const Workspace& workspace() const { return ws_; }
  /// Estimate of the largest stable step: min over elements of L_e / √(EA/ρA) (s).
  double EstimateCriticalStep() const;

 private:
  void CalcAcceleration(const VectorXd& q, const VectorXd& v, VectorXd* a);

  const Model& model_;
  Workspace ws_;
  DofMap dofs_;
  SparseLinearSolver mass_solver_;
  VectorXd rhs_;
  VectorXd a_free_;
  State previous_;
};

}  // namespace ancfnet
