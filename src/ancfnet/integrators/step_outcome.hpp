#pragma once
/// @file What one attempted time step reports to the time loop.

#include <string>

namespace ancfnet {

struct StepOutcome {
  bool accepted = false;
  int newton_iterations = 0;
  int jacobian_updates = 0;
  std::string failure;  ///< why the step was rejected
};

}  // namespace ancfnet
