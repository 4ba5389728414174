#pragma once
/// @file Energy accounting along a run: kinetic, strain and gravitational energy from the state,
/// work of applied loads and dissipation accumulated step by step.

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Kinetic energy ½ Σ v_eᵀ M_e v_e (J).
double CalcKineticEnergy(const Model& model, const Workspace& ws, const VectorXd& v);
/// Strain energy Σ U_e(q) of the cable elements plus the energy stored in the intact links (J).
double CalcStrainEnergy(const Model& model, const Workspace& ws, const VectorXd& q);

/// Which forces stand for a step in ∫ Q · dq: the mean of those at its two ends (trapezoidal
/// rule), or those at its middle, as the implicit midpoint rule uses them; with the latter the
/// discrete balance of kinetic energy is exact, ΔT = (Q_ext − Q_int)(q_{n+½}) · Δq.
enum class ForceQuadrature { kTrapezoidal, kMidpoint };

/// Accumulates the work of the applied loads W = ∫ Q_applied · dq and the energy dissipated by
/// material damping D = ∫ Q_visc · dq over each step (ForceQuadrature), and evaluates
/// the state energies. Gravity enters through its potential V = −λ Q_gᵀ q (Q_g constant); when λ
/// grows (static load steps) the work −∫ Q_gᵀ q dλ of raising it is added to W.
class EnergyTracker {
 public:
  /// Starts at `q` and load factor λ with the forces currently in `ws` (applied_force,
  /// viscous_force).
  EnergyTracker(const Model& model, const Workspace& ws, const VectorXd& q,
                double load_factor = 1.0,
                ForceQuadrature quadrature = ForceQuadrature::kTrapezoidal);
  /// Advances to the accepted state (q, v) with the forces in `ws` evaluated there (trapezoidal)
  /// or at the middle of the step (midpoint).
  void Advance(const Model& model, const Workspace& ws, const VectorXd& q, const VectorXd& v,
               double load_factor);
  /// After links failed at the current state: their stored energy `released` (J) leaves the
  /// strain energy and is counted as dissipated, and the forces now in `ws` (without them)
  /// start the next step.
  void Release(const Model& model, const Workspace& ws, double released);
  const EnergyAccount& account() const { return account_; }

 private:
  EnergyAccount account_;
  VectorXd q_;
  VectorXd applied_;
  VectorXd viscous_;
  double load_factor_ = 1.0;
  ForceQuadrature quadrature_;
};

}  // namespace ancfnet
