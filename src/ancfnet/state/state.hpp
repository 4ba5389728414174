#pragma once
/// @file State: time and the global coordinate vectors. Plain data; every computation takes
/// (const Model&, const State&, Workspace&).

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// What a contact pair remembers between steps (forces/target_contact.hpp, self_contact.hpp).
struct ContactPairHistory {
  /// Its impact speed v₀ (m/s, > 0, frozen while it touches), or minus its closing speed while
  /// apart (≤ 0), which is the v₀ of a pair that touches during the step.
  double speed = 0.0;
  /// The bristle deflection z (m) of the LuGre friction law at the end of the last accepted
  /// step, a vector in the tangent plane; zero while apart and without that law. In world
  /// coordinates, except for a target carried by a rigid body and a clearance joint's bearing on
  /// one: in the body's frame (z_W = R_WB z), so that it turns with the body.
  Vector3d bristle = Vector3d::Zero();
};

/// The history of a pair of self-contact primitives, kept for the pairs found near each other
/// at the last accepted step.
struct SelfContactPairHistory {
  int first = 0;   ///< primitive, first < second
  int second = 0;  ///< primitive
  ContactPairHistory history;
};

/// Time t (s) and the generalised coordinates q, velocities v = q̇ and accelerations a = q̈ of
/// every coordinate of the model, fixed ones included.
struct State {
  double t = 0.0;
  VectorXd q;
  VectorXd v;
  VectorXd a;
  /// Per spring-damper link of the model: 1 once it has failed (its tension passed its
  /// breaking force, or that of the cable it holds); it then carries no force.
  std::vector<char> link_broken;
  /// Per (contact probe, target) pair (forces/target_contact.hpp).
  std::vector<ContactPairHistory> contact_history;
  /// Sorted by (first, second).
  std::vector<SelfContactPairHistory> self_contact_history;
  /// Per clearance joint: its contact's impact speed and LuGre bristle
  /// (forces/clearance_joint_forces.hpp).
  std::vector<ContactPairHistory> joint_history;
  /// Per rigid body: its reference orientation R_ref, R_WB = R_ref exp(ψ̃) with ψ the body's
  /// rotation coordinates (model/rigid_body.hpp). R_WB(0) at t = 0; the integrators rebase it
  /// after every accepted step of a free body (RebaseBodyRotations).
  std::vector<Matrix3d> body_rotation;
  /// Per constraint equation of the ideal joints (forces/joint_constraints.hpp): its Lagrange
  /// multiplier λ, the reaction that holds it (N for a position equation, N m for a direction
  /// equation), at the last solved state.
  VectorXd multipliers;
};

/// The model's initial state at t = 0 (accelerations zero until an integrator computes them).
State MakeInitialState(const Model& model);

}  // namespace ancfnet
