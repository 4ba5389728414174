#pragma once
/// @file Failure of threads and connections: a spring-damper link whose tension reaches its
/// breaking force is removed, and so are the links holding a cable whose tension reaches the
/// cable's breaking force (a thread of a compliant net comes off its knots). Checked after
/// every accepted step; a failure is instantaneous, and the energy the link held is released.

#include <string>
#include <vector>

#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// One failure: the link or cable named `what` broke at time `time` (s) under `tension` (N).
struct FailureEvent {
  double time = 0.0;
  std::string what;
  double tension = 0.0;
};

/// What a check found: links newly broken and the elastic energy they held (J).
struct FailureCheck {
  int broken_links = 0;
  double released_energy = 0.0;
};

/// True when some link or cable of the model has a finite breaking force.
bool CanFail(const Model& model);

/// Marks in state->link_broken the intact links that fail at the state (their tension T(e, ė)
/// of the connection law, or the largest elastic tension of a cable they hold, CalcCableMaxTension
/// of analysis/cable_tension.hpp, at or above the breaking force), appends one event per failed
/// link or cable to `events`, and returns what broke. Allocates only when something fails.
FailureCheck ApplyFailures(const Model& model, State* state, std::vector<FailureEvent>* events);

}  // namespace ancfnet
