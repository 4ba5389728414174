#pragma once
/// @file Energy accounting along a run: kinetic, strain and gravitational energy from the state,
/// work of applied loads and dissipation accumulated step by step.

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Kinetic energy ½ Σ v_eᵀ M_e v_e, with ½ m |ẋ|² + ½ ωᵀ J_B ω of every rigid body (J).
double CalcKineticEnergy(const Model& model, const Workspace& ws, const VectorXd& v);
/// Strain energy Σ U_e(q) of the cable elements plus the energy stored in the intact links, the
/// body attachments and the clearance joints (with the reference orientations in
/// ws.body_rotation) and, as last evaluated into ws.contact_energy, in the contacts (J).
double CalcStrainEnergy(const Model& model, const Workspace& ws, const VectorXd& q);

/// How a step's work W and dissipation D are integrated (docs/theory.md, "Energy accounting"):
enum class EnergyQuadrature {
  /// Statics: W with the trapezoidal rule in q along the load path; nothing moves, D = 0.
  kLoadPath,
  /// W and D = ∫ Q_visc · dq with the trapezoidal rule in q, the quadrature that gives the
  /// change of the strain energy for the elastic forces: a snap shorter than the step is
  /// dissipated as the integrator's path dissipates it (the rule in time of the power q̇ᵀ Q_visc,
  /// used before, counted up to twice the energy lost at such snaps).
  kTrapezoidal,
  /// The implicit midpoint rule: W and D with the forces it left in the workspace at
  /// (q_{n+½}, v_{n+½}) = (q̄, v̄); the discrete kinetic-energy balance is then exact.
  kMidpoint,
};

/// Accumulates the work of the applied loads and of the prescribed motion,
/// W = ∫ (Q_applied + Q_drive) · dq (Workspace::drive_force), and the energy dissipated by
/// material damping D = ∫ q̇ · Q_visc dt over each step (EnergyQuadrature), and evaluates the
/// state energies. Gravity enters through its potential V = −λ Q_gᵀ q (Q_g constant); when λ
/// grows (static load steps) the work −∫ Q_gᵀ q dλ of raising it is added to W.
class EnergyTracker {
 public:
  /// Starts at `state` and load factor λ with the forces currently in `ws` (applied_force).
  EnergyTracker(const Model& model, const Workspace& ws, const State& state, double load_factor,
                EnergyQuadrature quadrature);
  /// Advances to the accepted state with the forces in `ws` evaluated there (kLoadPath,
  /// kTrapezoidal) or at the middle of the step (kMidpoint).
  void Advance(const Model& model, const Workspace& ws, const State& state, double load_factor);
  /// After links failed at the current state: their stored energy `released` (J) leaves the
  /// strain energy and is counted as dissipated, and the forces now in `ws` (without them)
  /// start the next step.
  void Release(const Model& model, const Workspace& ws, double released);
  const EnergyAccount& account() const { return account_; }
  /// Writes the account and the state and forces of the last step that the next step's
  /// quadrature starts from.
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Restores what SaveCheckpoint wrote (for the same model); throws InputError when a vector
  /// has the wrong length.
  void LoadCheckpoint(ArchiveReader* in);

 private:
  EnergyAccount account_;
  double t_ = 0.0;
  VectorXd q_;
  VectorXd applied_;
  VectorXd drive_;  // Workspace::drive_force at the last state
  double load_factor_ = 1.0;
  EnergyQuadrature quadrature_;
  VectorXd v_;
  VectorXd viscous_;            // Q_visc at the last state
  std::vector<Index> rebased_;  // rotation coordinates of free bodies (ψ reset to 0 every step)
};

}  // namespace ancfnet
