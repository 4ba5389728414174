#pragma once
/// @file Generalised-α time integration of M q̈ + Q_int(q, q̇) = Q_ext(q, t) (Chung & Hulbert
/// 1993) in the form of Arnold & Brüls (2007), where the true acceleration a satisfies the
/// equations of motion at t_{n+1} and an auxiliary acceleration ā carries the α-weighting.

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/integrators/implicit_step_core.hpp"
#include "ancfnet/integrators/step_outcome.hpp"

namespace ancfnet {

/// Coefficients for spectral radius at infinity ρ∞ ∈ [0, 1] (Arnold & Brüls 2007, eq. 12):
/// α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m, β = ¼ (γ + ½)².
/// Second-order accurate for every ρ∞; ρ∞ = 1 is the trapezoidal rule (no numerical damping).
struct GeneralizedAlphaCoefficients {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double gamma = 0.5;
  double beta = 0.25;
  static GeneralizedAlphaCoefficients FromSpectralRadius(double rho_infinity);
};

class GeneralizedAlphaIntegrator {
 public:
  GeneralizedAlphaIntegrator(const Model& model, const DynamicSettings& settings);

  /// Sets the consistent initial acceleration a₀ = M⁻¹ (Q_ext − Q_int)(q₀, v₀) and ā₀ = a₀.
  /// Returns false when the mass matrix is singular. Called again after a failure: the state's
  /// broken links are taken over and the stored Jacobian dropped.
  bool Initialize(State* state);
  /// Writes what the next steps depend on besides the state: ā and ImplicitStepCore's.
  void SaveCheckpoint(ArchiveWriter* out) const;
  /// Continues from `state` with what SaveCheckpoint wrote (instead of Initialize). Always true;
  /// throws InputError when `in` does not fit.
  bool Resume(const State& state, ArchiveReader* in);
  /// Advances `state` by h. On rejection the state is left unchanged.
  StepOutcome Step(double h, State* state);
  /// Forces evaluated at the last accepted state (for energy accounting).
  const Workspace& workspace() const { return core_.workspace(); }
  static constexpr EnergyQuadrature kEnergyQuadrature = EnergyQuadrature::kTrapezoidal;

  /// Newton problem of one step; its unknown is the free part of a_{n+1}.
  class StepProblem;

 private:
  ImplicitStepCore core_;
  GeneralizedAlphaCoefficients coefficients_;
  // Starting guess of a step's Newton iterations: a_{n+1} = a_n first; q_{n+1} = q_n on retry.
  enum class Predictor { kConstantAcceleration, kConstantPosition };
  Predictor predictor_ = Predictor::kConstantAcceleration;
  VectorXd a_bar_;  // auxiliary acceleration ā_n
};

}  // namespace ancfnet
