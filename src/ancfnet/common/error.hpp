#pragma once
/// @file The error types of ancfnet. Invalid input throws InputError, whose message is one line
/// meant for the user (the CLI prints it and exits with code 2). A solver that cannot go on throws
/// SolverError (exit code 3), after the outputs written so far have been flushed.

#include <stdexcept>
#include <string>

namespace ancfnet {

/// Invalid user input: a scene file, a CLI option or a call to the model-building API.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A solver failed for good (no convergence even at the smallest step, a singular matrix).
class SolverError : public std::runtime_error {
 public:
  SolverError(const std::string& message, double time)
      : std::runtime_error(message), time_(time) {}
  /// Simulated time (s) or load factor at which the failure happened.
  double time() const { return time_; }

 private:
  double time_;
};

}  // namespace ancfnet
