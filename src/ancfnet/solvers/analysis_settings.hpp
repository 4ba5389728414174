#pragma once
/// @file Options of the static and dynamic analyses: one description serves the YAML loader, the
/// CLI and (later) Python. Defaults are the documented defaults of docs/scene-format.md.

#include "ancfnet/assembly/contact_coupling_settings.hpp"

namespace ancfnet {

/// When Newton steps are damped (Deuflhard's natural monotonicity test, NewtonSolver).
enum class LineSearchMode {
  kAuto,    ///< plain Newton first; a load increment or time step it fails on is retried from
            ///< its start with damped steps before the increment or step is cut
  kAlways,  ///< every step damped when it does not contract
  kNever,   ///< plain Newton; failures go straight to step cutting
};

/// Convergence of Newton iterations: converged when the weighted RMS norm of the last increment,
/// √(mean_i (Δx_i / (atol + rtol |x_i|))²), is ≤ 1 (the error norm of Hairer & Wanner 1996, II.4)
/// and the energy of the last correction |Δqᵀ R| (J: the work of the residual force R over the
/// position increment Δq, twice the strain energy left in the stiffest modes) is ≤ energy_tolerance
/// times the energy the step exchanges (kinetic energy plus |work| of internal and applied forces
/// over the step): docs/theory.md, "Convergence of Newton's method". The second test keeps stiff
/// systems honest, where a position increment below rtol still leaves large forces.
struct NewtonSettings {
  int max_iterations = 12;
  double relative_tolerance = 1e-6;  ///< rtol (dimensionless)
  double absolute_tolerance = 1e-8;  ///< atol (in the unit of the coordinates, m or 1)
  double energy_tolerance = 1e-6;    ///< η_E (dimensionless)
  LineSearchMode line_search = LineSearchMode::kAuto;
};

/// When the iteration matrix is recomputed and factorised.
enum class JacobianUpdate {
  kEveryIteration,  ///< full Newton
  kEveryStep,       ///< once per time step, kept through that step's iterations
  kAdaptive,        ///< kept across steps; refreshed when convergence slows or fails
};

enum class IntegratorType {
  kGeneralizedAlpha,  ///< generalised-α with numerical damping ρ∞
                      ///< (integrators/generalized_alpha.hpp)
  kImplicitMidpoint,  ///< implicit midpoint: conserves momentum (integrators/implicit_midpoint.hpp)
  kExplicitVerlet,    ///< explicit velocity Verlet, conditionally stable
};

struct DynamicSettings {
  IntegratorType integrator = IntegratorType::kGeneralizedAlpha;
  double spectral_radius = 0.8;  ///< ρ∞ ∈ [0, 1] of generalised-α
  double time_step = 1e-3;       ///< nominal step h (s), > 0
  double end_time = 1.0;         ///< s, > 0
  double min_time_step = 0.0;    ///< smallest step after cuts (s); 0: time_step / 2¹⁰
  JacobianUpdate jacobian_update = JacobianUpdate::kAdaptive;
  /// Energy step control: the largest drift of the energy balance (kinetic + strain + gravity +
  /// dissipated − work) over the run, as a fraction of the energy scale (the largest
  /// kinetic + strain + |gravity| + |work| + dissipated so far), that the step size is held to
  /// (solvers/energy_step_control.hpp); 0 (the default): off, steps of time_step unless cut.
  /// Off by default: a scene that starts at rest has no energy scale yet, and the control then
  /// cuts the step for rounding; a net resting on a target loses energy to the numerical damping
  /// of contact no step resolves, and the control then cuts the step to no avail.
  double energy_drift = 0.0;
  NewtonSettings newton;
  ContactCouplingSettings contact_couplings;  ///< of the implicit integrators' iteration matrix

  /// The smallest step the time loop cuts to: min_time_step, or time_step / 2¹⁰ when 0.
  double smallest_step() const { return min_time_step > 0.0 ? min_time_step : time_step / 1024.0; }
};

struct StaticSettings {
  int load_steps = 1;      ///< equal load increments to reach the full load, ≥ 1
  int max_step_cuts = 12;  ///< halvings of a load increment before giving up
  NewtonSettings newton{.max_iterations = 40};
};

enum class AnalysisType { kStatic, kDynamic };

struct AnalysisSettings {
  AnalysisType type = AnalysisType::kStatic;
  StaticSettings statics;
  DynamicSettings dynamics;
};

}  // namespace ancfnet
