#pragma once
/// @file The time loop: one step is predict → Newton (inside the integrator) → accept or cut the
/// step → energy account → outputs.

#include <cstddef>
#include <functional>
#include <vector>

#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"
#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {

/// Checkpoints of the time loop: the complete state of the integration, from which a later run
/// continues bit for bit as if it had never stopped.
struct TimeLoopCheckpoints {
  /// Simulated time between checkpoints (s): one is taken after the first step that reaches
  /// t₀ + k·every, and one when an interrupt stops the run (before the state reached is handed
  /// to the outputs). 0: none.
  double every = 0.0;
  /// Called at each checkpoint with the state reached and the time loop's part of the
  /// checkpoint: the state, the step control, the integrator's memory (ā, contact couplings, the
  /// Jacobian in use), the energy account and the statistics. The caller adds its own (the
  /// outputs') and writes the file; it may throw InputError when it cannot. Required when
  /// every > 0.
  std::function<void(const State& state, const std::vector<std::byte>& loop)> write = nullptr;
  /// Continue from this part of a checkpoint (read to its end) instead of starting at the given
  /// state; nothing is handed to `output` before the first step. Null: start afresh.
  ArchiveReader* resume = nullptr;
};

/// Called with the state after each accepted step, once its failures are applied and before its
/// output (metrics that must not wait for the output times: the first contact of a capture).
using StepCallback = std::function<void(const State& state)>;

/// Integrates from state->t to settings.end_time. A rejected step is retried with half the
/// step, down to min_time_step (then the run stops cleanly: the result says when and why); after
/// four accepted steps in a row a reduced step doubles back towards time_step. Steps are
/// shortened to land on the output times, multiples of `output_interval` (0: every step).
/// `output` is called at the start and at each output time, `step` (when set) after every
/// accepted step. Never throws for a failed solve;
/// throws InputError when `checkpoints.resume` does not fit the model or a checkpoint cannot be
/// written.
SolveResult SolveDynamic(const Model& model, const DynamicSettings& settings,
                         double output_interval, const OutputCallback& output, State* state,
                         const TimeLoopCheckpoints& checkpoints = {},
                         const StepCallback& step = nullptr);

}  // namespace ancfnet
