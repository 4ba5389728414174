#include "ancfnet/integrators/dynamic_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/integrators/explicit_verlet.hpp"
#include "ancfnet/integrators/generalized_alpha.hpp"
#include "ancfnet/integrators/implicit_midpoint.hpp"
#include "ancfnet/solvers/energy_step_control.hpp"

namespace ancfnet {
namespace {

// Accepted steps in a row before a reduced step may grow again.
constexpr int kStepsBeforeGrowth = 4;

template <class Integrator>
SolveResult RunTimeLoop(const Model& model, const DynamicSettings& settings, double output_interval,
                        const OutputCallback& output, Integrator& integrator, State* state) {
  SolveResult result;
  if (!integrator.Initialize(state)) {
    result.completed = false;
    result.message = "the mass matrix is singular";
    return result;
  }
  EnergyTracker energy(model, integrator.workspace(), *state, 1.0, Integrator::kEnergyQuadrature);
  energy.Advance(model, integrator.workspace(), *state, 1.0);
  if (!EmitOutput(output, *state, energy.account(), &result)) return result;

  const double nominal = settings.time_step;
  const double min_step = settings.smallest_step();
  const double end = settings.end_time;
  const double time_eps = 1e-9 * nominal;
  double step = nominal;
  // Output times t₀ + k Δ, computed from k so that they carry no summed round-off.
  const double start = state->t;
  long output_count = 1;
  double next_output = start + (output_interval > 0.0 ? output_interval : 0.0);
  int accepted_in_a_row = 0;
  EnergyStepControl energy_control(settings.energy_drift, start, end, energy.account());
  const bool can_fail = CanFail(model);
  while (state->t < end - time_eps) {
    double h = std::min(step, end - state->t);
    if (output_interval > 0.0) h = std::min(h, next_output - state->t);
    const StepOutcome outcome = integrator.Step(h, state);
    result.statistics.newton_iterations += outcome.newton_iterations;
    result.statistics.jacobian_updates += outcome.jacobian_updates;
    result.statistics.pattern_rebuilds += outcome.pattern_rebuilds;
    if (!outcome.accepted) {
      ++result.statistics.step_cuts;
      ++result.statistics.step_cut_reasons[StepCutReason(outcome.failure)];
      accepted_in_a_row = 0;
      step = 0.5 * h;
      if (step < min_step) {
        result.completed = false;
        result.message = fmt::format(
            "time step failed at t = {:.9g} s even with h = {:.3g} s (minimum {:.3g} s): {}",
            state->t, h, min_step, outcome.failure);
        return result;
      }
      continue;
    }
    ++result.statistics.steps;
    result.statistics.max_constraint_violation =
        std::max(result.statistics.max_constraint_violation, outcome.constraint_violation);
    // Land exactly on output and end times (no round-off from summing steps).
    if (std::abs(state->t - end) <= time_eps) state->t = end;
    if (output_interval > 0.0 && std::abs(state->t - next_output) <= time_eps)
      state->t = next_output;
    energy.Advance(model, integrator.workspace(), *state, 1.0);
    if (can_fail) {
      const FailureCheck check = ApplyFailures(model, state, &result.failures);
      if (check.broken_links > 0) {
        // The forces jump: restart from the consistent acceleration without the broken links.
        if (!integrator.Initialize(state)) {
          result.completed = false;
          result.message =
              fmt::format("the mass matrix is singular after a failure at t = {:.9g} s", state->t);
          return result;
        }
        energy.Release(model, integrator.workspace(), check.released_energy);
      }
    }
    const double cut = energy_control.Cut(h, energy.account());
    if (cut < 1.0) {
      // A power-of-two fraction of the nominal step, so that the step (and with it the
      // iteration matrix, which depends on h) changes seldom.
      step = std::max(nominal * std::exp2(std::floor(std::log2(cut * h / nominal))), min_step);
      accepted_in_a_row = 0;
    } else if (!energy_control.may_grow()) {
      accepted_in_a_row = 0;
    } else if (++accepted_in_a_row >= kStepsBeforeGrowth && step < nominal) {
      step = std::min(2.0 * step, nominal);
      accepted_in_a_row = 0;
    }
    const bool at_output =
        output_interval <= 0.0 || state->t >= next_output - time_eps || state->t >= end - time_eps;
    if (at_output) {
      if (!EmitOutput(output, *state, energy.account(), &result)) return result;
      if (output_interval > 0.0)
        while (next_output <= state->t + time_eps)
          next_output = start + static_cast<double>(++output_count) * output_interval;
    }
    if (StopIfInterrupted(output, *state, energy.account(), at_output, &result)) return result;
  }
  return result;
}

}  // namespace

SolveResult SolveDynamic(const Model& model, const DynamicSettings& settings,
                         double output_interval, const OutputCallback& output, State* state) {
  if (model.num_constraint_equations() > 0 &&
      settings.integrator != IntegratorType::kGeneralizedAlpha)
    throw InputError(fmt::format(
        "the {} integrator does not support ideal joints (constraints with Lagrange "
        "multipliers); use integrator: generalized_alpha",
        settings.integrator == IntegratorType::kExplicitVerlet ? "explicit_verlet"
                                                               : "midpoint"));
  switch (settings.integrator) {
    case IntegratorType::kExplicitVerlet: {
      ExplicitVerletIntegrator integrator(model);
      return RunTimeLoop(model, settings, output_interval, output, integrator, state);
    }
    case IntegratorType::kImplicitMidpoint: {
      ImplicitMidpointIntegrator integrator(model, settings);
      return RunTimeLoop(model, settings, output_interval, output, integrator, state);
    }
    case IntegratorType::kGeneralizedAlpha:
      break;
  }
  GeneralizedAlphaIntegrator integrator(model, settings);
  return RunTimeLoop(model, settings, output_interval, output, integrator, state);
}

}  // namespace ancfnet
