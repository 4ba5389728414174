#pragma once
/// @file Prescribed motion of fixed coordinates: a point moving at a constant velocity (a
/// chaser), or a clamped node turning with a hub, r(t) = c + R(θ(t)) (r₀ − c) and
/// r'(t) = R(θ(t)) r'₀, R the rotation by θ about a fixed axis, for a given angle history θ(t)
/// (a spin-up manoeuvre, a constant rate). The coordinates stay eliminated from the unknowns; the
/// integrators set their q, q̇ and q̈ at each time.

#include <array>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// θ(t) of a hub (rad), with θ̇ and θ̈.
struct AngleProfile {
  enum class Kind {
    kConstantRate,  ///< θ = Ω t
    /// The spin-up of Kane, Ryan & Banerjee (1987): θ = (Ω/T)[t²/2 + (T/2π)²(cos(2πt/T) − 1)] for
    /// t ≤ T, then Ω (t − T/2): the rate rises smoothly from 0 to Ω in the time T.
    kSpinUp,
  };
  Kind kind = Kind::kConstantRate;
  double rate = 0.0;       ///< Ω (rad/s)
  double ramp_time = 0.0;  ///< T (s), > 0 for kSpinUp
  /// {θ, θ̇, θ̈} at time t ≥ 0.
  std::array<double, 3> Evaluate(double t) const;
};

/// Three fixed coordinates (a point mass's position, or a node's position or slope) and how they
/// move from their initial value x₀.
struct PrescribedBlock {
  enum class Kind {
    kTranslation,  ///< x(t) = x₀ + v t
    kRotation,     ///< x(t) = c + R(θ(t)) (x₀ − c), or R(θ(t)) x₀ for a direction (a slope)
  };
  Kind kind = Kind::kTranslation;
  Index dof = 0;
  Vector3d initial = Vector3d::Zero();
  Vector3d velocity = Vector3d::Zero();  ///< kTranslation
  Vector3d axis = Vector3d::UnitZ();     ///< kRotation: unit vector
  Vector3d center = Vector3d::Zero();    ///< kRotation: a point of the axis (positions only)
  bool is_direction = false;             ///< kRotation: a slope, turned without the centre
  AngleProfile angle;                    ///< kRotation
};

/// Sets the coordinates of every block at time t in q, and their rates in v and a (either may be
/// null).
void ApplyPrescribedMotion(const std::vector<PrescribedBlock>& blocks, double t, VectorXd* q,
                           VectorXd* v, VectorXd* a);

}  // namespace ancfnet
