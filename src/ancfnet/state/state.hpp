#pragma once
/// @file State: time and the global coordinate vectors. Plain data; every computation takes
/// (const Model&, const State&, Workspace&).

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// What a pair of self-contact primitives (forces/self_contact.hpp) remembers between steps:
/// like State::contact_history, its impact speed (> 0) while it touches, or minus its closing
/// speed while apart (≤ 0). Kept for the pairs found near each other at the last accepted step.
struct SelfContactPairHistory {
  int first = 0;   ///< primitive, first < second
  int second = 0;  ///< primitive
  double value = 0.0;
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
  /// Per (contact probe, target) pair: its impact speed (m/s, > 0) while it touches, minus its
  /// closing speed while apart (forces/target_contact.hpp).
  std::vector<double> contact_history;
  /// Sorted by (first, second).
  std::vector<SelfContactPairHistory> self_contact_history;
  /// Per rigid body: its reference orientation R_ref, R_WB = R_ref exp(ψ̃) with ψ the body's
  /// rotation coordinates (model/rigid_body.hpp). R_WB(0) at t = 0; the integrators rebase it
  /// after every accepted step of a free body (RebaseBodyRotations).
  std::vector<Matrix3d> body_rotation;
};

/// The model's initial state at t = 0 (accelerations zero until an integrator computes them).
State MakeInitialState(const Model& model);

}  // namespace ancfnet
