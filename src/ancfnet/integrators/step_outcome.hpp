#pragma once
/// @file What one attempted time step reports to the time loop.

#include <string>

namespace ancfnet {

struct StepOutcome {
  bool accepted = false;
  int newton_iterations = 0;
  int jacobian_updates = 0;
  int pattern_rebuilds = 0;  ///< of the iteration matrix, for contact couplings that came or went
  std::string failure;       ///< why the step was rejected
  /// max_i |g_i| of the ideal joints at the accepted state (0 without joints).
  double constraint_violation = 0.0;
};

}  // namespace ancfnet
