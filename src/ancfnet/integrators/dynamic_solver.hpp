#pragma once
/// @file The time loop: one step is predict → Newton (inside the integrator) → accept or cut the
/// step → energy account → outputs.

#include "ancfnet/model/model.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"
#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {

/// Integrates from state->t to settings.end_time. A rejected step is retried with half the
/// step, down to min_time_step (then the run stops cleanly: the result says when and why); after
/// four accepted steps in a row a reduced step doubles back towards time_step. Steps are
/// shortened to land on the output times, multiples of `output_interval` (0: every step).
/// `output` is called at the start and at each output time. Never throws for a failed solve.
SolveResult SolveDynamic(const Model& model, const DynamicSettings& settings,
                         double output_interval, const OutputCallback& output, State* state);

}  // namespace ancfnet
