#pragma once
/// @file A floating-frame, assumed-modes model of a beam clamped to a hub that turns in its plane
/// by a prescribed angle θ(t): the comparison model of the ANCF spin-up benchmark. The transverse
/// deflection in the rotating frame is v(x, t) = Σ ψ_i(x) q_i(t) over clamped–free Euler–Bernoulli
/// modes, with linear elasticity and no geometric (centrifugal) stiffening, so that
///   q̈_i + (ω_i² − θ̇²) q_i = −θ̈ ∫₀ᴸ ρA x ψ_i dx
/// (mass-normalised ψ_i; Kane, Ryan & Banerjee 1987, the "conventional" linear model). Above
/// θ̇ = ω₁ the first mode has negative stiffness and the response grows without bound.

#include <vector>

#include "ancfnet/model/prescribed_motion.hpp"

namespace ancfnet {

struct AssumedModesBeam {
  double length = 1.0;             ///< L (m), > 0
  double bending_stiffness = 1.0;  ///< EI (N m²), > 0
  double mass_per_length = 1.0;    ///< ρA (kg/m), > 0
  int num_modes = 3;               ///< 1 … 6
};

struct AssumedModesResponse {
  std::vector<double> time;            ///< s
  std::vector<double> tip_deflection;  ///< v(L, t) in the rotating frame (m)
  std::vector<double> omega;           ///< the modes' ω_i (rad/s)
};

/// Integrates the model from rest with the classical Runge–Kutta scheme at step h (s) to
/// end_time, recording every step. Stops early (the last sample then being the first to exceed
/// it) when |v(L)| passes `divergence_limit` (m): the linear model has diverged.
AssumedModesResponse SimulateAssumedModes(const AssumedModesBeam& beam, const AngleProfile& hub,
                                          double end_time, double h, double divergence_limit);

}  // namespace ancfnet
