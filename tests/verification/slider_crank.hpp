#pragma once
/// @file The crank and connecting rod of the slider-crank benchmark of Flores & Ambrósio (2004):
/// crank r = 0.05 m at 5000 rpm, rod l = 0.12 m; at θ = 0 the slider's acceleration is
/// −r ω² (1 + r/l), at θ = π it is r ω² (1 − r/l). The slider and the joints are the tests' own.

#include <cmath>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet::verification::slider_crank {

inline constexpr double kCrank = 0.05;                                    // r (m)
inline constexpr double kRod = 0.12;                                      // l (m)
inline constexpr double kOmega = 5000.0 * 2.0 * std::numbers::pi / 60.0;  // rad/s
inline constexpr double kPeriod = 2.0 * std::numbers::pi / kOmega;        // s

/// The slider's acceleration of the ideal mechanism at crank angle θ, the crank turning at the
/// constant ω: x = r cos θ + S, S = √(l² − r² sin² θ), differentiated twice,
///   ẍ = −r ω² cos θ − r² ω² [cos 2θ / S + r² sin² θ cos² θ / S³]
/// (the exact form of −r ω² (cos θ + (r/l) cos 2θ + …); Flores & Ambrósio 2004).
inline double CalcIdealSliderAcceleration(double theta) {
  const double s = std::sqrt(kRod * kRod - std::pow(kCrank * std::sin(theta), 2));
  const double sin_cos = std::sin(theta) * std::cos(theta);
  return -kCrank * kOmega * kOmega * std::cos(theta) -
         std::pow(kCrank * kOmega, 2) *
             (std::cos(2.0 * theta) / s + std::pow(kCrank * sin_cos, 2) / (s * s * s));
}

/// Generalised-α over `turns` turns at h = T/2400 with spectral radius ρ∞. Newton's test is on
/// the positions, q = q̂ + β' a with β' ≈ 6e-12 s²: a tolerance of 1e-10 |q| resolves the
/// accelerations to ~1 m/s² (examples/slider_crank.yaml).
inline DynamicSettings MakeSliderCrankSettings(double turns, double spectral_radius) {
  DynamicSettings settings;
  settings.time_step = kPeriod / 2400.0;
  settings.end_time = turns * kPeriod;
  settings.spectral_radius = spectral_radius;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-12;
  return settings;
}

/// The crank, a prescribed body turning at ω about z at the origin (θ = 0 at t = 0: along x).
inline void AddCrank(ModelBuilder* builder) {
  builder->AddRigidBody({.name = "crank",
                         .mass = 0.30,
                         .inertia = Vector3d(1e-4, 1e-4, 1e-4).asDiagonal(),
                         .angular_velocity = Vector3d(0, 0, kOmega),
                         .motion = BodyMotion::kPrescribed});
}

/// The crank (AddCrank) and the rod, a free body along x at θ = 0 (its centre at r + l/2),
/// moving as the mechanism moves there: the slider at rest, the rod turning at −r ω/l.
inline void AddCrankAndRod(ModelBuilder* builder) {
  AddCrank(builder);
  builder->AddRigidBody({.name = "rod",
                         .mass = 0.21,
                         .inertia = Vector3d(1e-5, 2.5e-4, 2.5e-4).asDiagonal(),
                         .position = Vector3d(kCrank + 0.5 * kRod, 0, 0),
                         .velocity = Vector3d(0, 0.5 * kCrank * kOmega, 0),
                         .angular_velocity = Vector3d(0, 0, -kCrank * kOmega / kRod)});
}

}  // namespace ancfnet::verification::slider_crank
