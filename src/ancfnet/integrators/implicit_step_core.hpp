#pragma once
/// @file What the implicit integrators (generalised-α, implicit midpoint) share: the numbering of
/// the unknowns, scratch, the full mass matrix, the iteration matrix and its Newton solver, and
/// the state at t_n while a step is attempted. Each integrator keeps only its own update formulas.

#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"
#include "ancfnet/solvers/newton.hpp"
#include "ancfnet/solvers/solve_result.hpp"
#include "ancfnet/solvers/system_forces.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

class ImplicitStepCore {
 public:
  ImplicitStepCore(const Model& model, const DynamicSettings& settings);

  /// Takes over the state's broken links, drops the stored Jacobian (also after a failure) and
  /// sets the consistent acceleration a = M⁻¹ (Q_ext − Q_int). False when M is singular.
  bool Initialize(State* state);
  /// Writes what the next steps depend on besides the state: the last step size, the contact
  /// couplings of the iteration matrix and Newton's Jacobian reuse with its factorisation.
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Continues from `state`, reached by an earlier run whose SaveCheckpoint wrote `in`: what
  /// Initialize does, except that the acceleration is the state's and the step size, the
  /// couplings and the factorisation are those written. Throws InputError when `in` does not fit.
  void Resume(const State& state, ArchiveReader* in);
  /// Saves the state at t_n (its contact history and body rotations included; ws() evaluates the
  /// bodies with the latter until AcceptStep); drops the factorisation when h changed (the
  /// iteration matrix depends on h; so do the contacts' LuGre bristles, stepped over h).
  void BeginStep(double h, const State& state);
  /// After BeginStep, contact detection for the step of size h from `state`: finds the
  /// self-contact pairs to watch during the step and the probes near a body, and updates the
  /// contact couplings of the iteration matrix; true when that gave it a new pattern (which the
  /// linear solver then analyses anew).
  bool DetectContacts(double h, const State& state);
  /// For a scheme that evaluates the forces at the step's midpoint: from now until AcceptStep the
  /// contact forces' elastic parts are discrete gradients between the saved state and *q_end,
  /// which the integrator keeps at the end of the step it is solving for (TargetContact::SetStep;
  /// docs/theory.md, "Energy-consistent contact"). Call after BeginStep.
  void SetStepEnd(const VectorXd* q_end);
  /// Empty when a converged step to (q, v) may be accepted, else why not (self-contact search
  /// margin exceeded, threads passed through each other, a probe sank too far into a target;
  /// the last only while half the step is still above the time loop's smallest step, so that a
  /// probe too fast to resolve does not stop the run).
  std::string CheckStep(const VectorXd& q, const VectorXd& v) const;
  /// After a converged step: the contact history at the new state; the bodies' reference
  /// orientations rebased (R_ref ← R_ref exp(ψ̃), ψ ← 0), in the state and in ws().
  void AcceptStep(State* state);
  /// ws().drive_force at `state`, from the forces now in ws() (evaluated at that state) and the
  /// state's acceleration, which must satisfy M a = Q_ext − Q_int at the free coordinates.
  void CalcDriveForce(const State& state);
  /// Newton iterations on `problem` with the shared solver.
  template <class Problem>
  NewtonResult Solve(Problem& problem) {
    return newton_.Solve(problem);
  }

  /// Number of constraint equations of the ideal joints (multipliers after the unknowns).
  Index num_constraints() const { return constraints_.size(); }
  /// r = (M a + Q_int(q, v) − Q_ext(q)) restricted to the unknowns; the forces stay in ws().
  /// With ideal joints, r = (M a + Q_int − Q_ext + Gᵀλ, g/c_K) over the unknowns and the
  /// multipliers λ: the constraint rows scaled by 1/c_K, c_K = ∂q/∂x the stiffness weight of
  /// the iteration matrix, so that they enter it as G (docs/theory.md, "Ideal joints").
  void CalcResidual(const VectorXd& q, const VectorXd& v, const VectorXd& a,
                    const VectorXd& multipliers, double constraint_scale, VectorXd* r);
  /// c_M M + c_C C + c_K K at (q, v) over the unknowns (C with Rayleigh damping; the dense modal
  /// damping matrix is left out). With ideal joints the bordered
  /// [c_M M + c_C C + c_K (K + ∂(Gᵀλ)/∂q)  Gᵀ; G  0] over the unknowns and λ.
  const SparseMatrixd& CalcIterationMatrix(const VectorXd& q, const VectorXd& v,
                                           const VectorXd& multipliers,
                                           const IterationWeights& weights);
  /// max_i |g_i| of the ideal joints at (q, v) (0 without joints).
  double ConstraintViolation(const VectorXd& q, const VectorXd& v);
  /// Forces at (q, v) into ws(), damping models included.
  void CalcForces(const VectorXd& q, const VectorXd& v);
  /// Weighted RMS norm of the position change scale · Δa (the first num_unknowns entries of Δa),
  /// each coordinate against the scale of its kind (CalcIncrementWeights); with ideal joints at
  /// least the scaled violation of the last CalcResidual (JointConstraints::ScaledViolation), so
  /// that Newton converges only where the constraints hold to its tolerances.
  double IncrementNorm(const VectorXd& da, double scale) const;
  /// |(q − q_n)ᵀ R| (J) over the unknowns: the work of the residual's force rows over the step
  /// from the previous state to positions q (CalcResidualWork).
  double ResidualWork(const VectorXd& q, const VectorXd& r) const {
    return CalcResidualWork(q, previous_.q, dofs_.coordinates(), r);
  }
  /// The energy a step from the saved state to (q, v) exchanges, the scale of Newton's energy
  /// test (NewtonSettings): ½ vᵀ M v + |Δqᵀ Q_int| + |Δqᵀ Q_ext| with Δq = q − q_n and the
  /// forces of the last CalcResidual (J).
  double EnergyScale(const VectorXd& q, const VectorXd& v) const;

  const DofMap& dofs() const { return dofs_; }
  const Model& model() const { return model_; }
  const State& previous() const { return previous_; }
  const Workspace& workspace() const { return ws_; }

 private:
  // The state's broken links, body rotations and joint histories into ws_.
  void TakeOver(const State& state);

  const Model& model_;
  Workspace ws_;
  SystemForces forces_;
  // Owner pairs that must be coupled in this step, and those worth coupling.
  std::vector<std::pair<Index, Index>> required_couplings_, near_couplings_;
  DofMap dofs_;
  SystemMatrix iteration_matrix_;
  JointConstraints constraints_;
  SparseMatrixd bordered_;  // with ideal joints: the bordered iteration matrix
  VectorXd residual_free_;
  SparseMatrixd mass_;  // all coordinates
  NewtonSolver newton_;
  NewtonSettings newton_settings_;
  VectorXd increment_weights_;  // of the convergence norm, per unknown (CalcIncrementWeights)
  double last_h_ = 0.0;
  double smallest_step_;  // DynamicSettings::smallest_step()
  State previous_;
  VectorXd residual_full_;
};

}  // namespace ancfnet
