#pragma once
/// @file The spinning steel cantilever of beam elements shared by the beam dynamics cases: 1 m,
/// 20 × 10 mm, 8 elements, root clamped, spinning about its axis at 20 rad/s at t = 0, under
/// gravity. Scene text without its `analysis`, and the tip's twist.

#include <cmath>

#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet::verification {

inline constexpr const char* kSpinningBeamCantilever = R"(gravity: [0, 0, -9.81]
materials:
  steel: {youngs_modulus: 2.0e11, density: 7800, poisson_ratio: 0.3}
sections:
  bar: {shape: rectangle, width: 0.02, height: 0.01}
cables:
  - {name: bar, element: ancf_beam, orientation: [0, 0, 1], start: [0, 0, 0], end: [1, 0, 0],
     elements: 8, material: steel, section: bar, initial_velocity: {angular: [20, 0, 0]}}
constraints:
  - {type: clamp, at: bar.start}
)";

/// Twist of the tip about x: d₂ = e_z turns to (0, −sin φ, cos φ).
inline double TipTwist(const Model& model, const State& state) {
  const Vector3d d2 = state.q.segment<3>(model.nodes().back().section_dof);
  return std::atan2(-d2.y(), d2.z());
}

}  // namespace ancfnet::verification
