#pragma once
/// @file State: time and the global coordinate vectors. Plain data; every computation takes
/// (const Model&, const State&, Workspace&).

#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// Time t (s) and the generalised coordinates q, velocities v = q̇ and accelerations a = q̈ of
/// every coordinate of the model, fixed ones included.
struct State {
  double t = 0.0;
  VectorXd q;
  VectorXd v;
  VectorXd a;
};

/// The model's initial state at t = 0 (accelerations zero until an integrator computes them).
State MakeInitialState(const Model& model);

}  // namespace ancfnet
