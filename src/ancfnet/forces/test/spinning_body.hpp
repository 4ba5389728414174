#pragma once
/// @file Test helper: a free rigid body in a general pose, moving and spinning, for the Jacobian
/// tests of the joints.

#include <string>

#include "ancfnet/model/model_builder.hpp"

namespace ancfnet::test {

/// A 2 kg body at `position`, turned by `angle` about (1, 2, 3), with inertia (0.02, 0.03, 0.04)
/// kg m², velocity (0.05, −0.02, 0.01) m/s and spin (3, −5, 7) rad/s.
inline void AddSpinningBody(const std::string& name, const Vector3d& position, double angle,
                            ModelBuilder* builder) {
  builder->AddRigidBody(
      {.name = name,
       .mass = 2.0,
       .inertia = Vector3d(0.02, 0.03, 0.04).asDiagonal(),
       .position = position,
       .orientation = Eigen::AngleAxisd(angle, Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
       .velocity = Vector3d(0.05, -0.02, 0.01),
       .angular_velocity = Vector3d(3.0, -5.0, 7.0)});
}

}  // namespace ancfnet::test
