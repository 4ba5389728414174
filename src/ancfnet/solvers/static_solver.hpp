#pragma once
/// @file Static equilibrium Q_int(q) = λ Q_ext(q) by Newton–Raphson with load stepping,
/// backtracking line search and automatic cutting of the load increment.

#include "ancfnet/model/model.hpp"
#include "ancfnet/solvers/analysis_settings.hpp"
#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {

/// Raises the load factor λ from 0 to 1 in `load_steps` equal increments; an increment whose
/// Newton iterations fail is halved (at most max_step_cuts times in a row) and grown back after
/// successes. `state` starts at the initial configuration and ends at the last equilibrium found
/// (state->t holds its load factor). `output` is called at λ = 0 and after every accepted
/// increment. Never throws for a failed solve: the result says where and why.
SolveResult SolveStatic(const Model& model, const StaticSettings& settings,
                        const OutputCallback& output, State* state);

}  // namespace ancfnet
