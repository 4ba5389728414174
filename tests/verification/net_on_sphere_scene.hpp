#pragma once
/// @file The S3 scene (examples/net_drop_sphere.yaml) shrunk to 4 × 4 meshes, as scene text
/// without its analysis block: linear ANCF threads (E = 1 GPa, 2 mm, Kelvin–Voigt τ = 10⁻⁴ s),
/// ideal knots, Carvalho–Martins contact with tanh friction on a sphere of radius 0.3 m.

#include <string>

#include <fmt/format.h>

namespace ancfnet::verification {

/// A square net of side `side` (m) flat at height `height` (m) above the sphere's centre.
inline std::string SmallNetOnSphereScene(double side, double height) {
  return fmt::format(R"(gravity: [0, 0, -9.81]
materials:
  thread: {{youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-4}}
sections:
  thread: {{shape: circle, diameter: 0.002}}
nets:
  - {{name: net, type: square, side: {}, meshes: 4, center: [0, 0, {}], material: thread,
     section: thread, knot_model: ideal, tension_only: false}}
contact:
  law: {{type: carvalho_martins, stiffness: 1.0e6, restitution: 0.3}}
  friction: {{type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-2}}
  points_per_element: 8
  targets:
    - {{name: ball, type: sphere, center: [0, 0, 0], radius: 0.3}}
)",
                     side, height);
}

}  // namespace ancfnet::verification
