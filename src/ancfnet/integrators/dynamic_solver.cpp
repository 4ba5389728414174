#include "ancfnet/integrators/dynamic_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"
#include "ancfnet/integrators/explicit_verlet.hpp"
#include "ancfnet/integrators/generalized_alpha.hpp"
#include "ancfnet/integrators/implicit_midpoint.hpp"
#include "ancfnet/solvers/energy_step_control.hpp"
#include "ancfnet/state/state_archive.hpp"

namespace ancfnet {
namespace {

// Accepted steps in a row before a reduced step may grow again.
constexpr int kStepsBeforeGrowth = 4;

// Where the time loop stands besides the state: what a checkpoint carries of it.
struct LoopPosition {
  double start = 0.0;          // t₀ of the first run
  double step = 0.0;           // the step to try next
  long output_count = 1;       // the next output is at t₀ + output_count Δ ...
  double next_output = 0.0;    // ... this time
  int accepted_in_a_row = 0;

  void Save(ArchiveWriter* out) const {
    out->Write(start);
    out->Write(step);
    out->Write(output_count);
    out->Write(next_output);
    out->Write(accepted_in_a_row);
  }
  void Load(ArchiveReader* in) {
    start = in->Read<double>();
    step = in->Read<double>();
    output_count = in->Read<long>();
    next_output = in->Read<double>();
    accepted_in_a_row = in->Read<int>();
  }
};

template <class Integrator>
SolveResult RunTimeLoop(const Model& model, const DynamicSettings& settings, double output_interval,
                        const OutputCallback& output, const TimeLoopCheckpoints& checkpoints,
                        const StepCallback& step, Integrator& integrator, State* state) {
  SolveResult result;
  LoopPosition at;
  ArchiveReader* resume = checkpoints.resume;
  if (resume) {
    LoadState(resume, state);
    at.Load(resume);
    LoadCheckpoint(resume, &result);
  }
  if (!(resume ? integrator.Resume(*state, resume) : integrator.Initialize(state))) {
    result.completed = false;
    result.message = "the mass matrix is singular";
    return result;
  }
  EnergyTracker energy(model, integrator.workspace(), *state, 1.0, Integrator::kEnergyQuadrature);
  if (resume) {
    energy.LoadCheckpoint(resume);
  } else {
    energy.Advance(model, integrator.workspace(), *state, 1.0);
    // Output times t₀ + k Δ, computed from k so that they carry no summed round-off.
    at.start = state->t;
    at.step = settings.time_step;
    at.next_output = at.start + (output_interval > 0.0 ? output_interval : 0.0);
    if (!EmitOutput(output, *state, energy.account(), &result)) return result;
  }
  EnergyStepControl energy_control(settings.energy_drift, at.start, settings.end_time,
                                   energy.account());
  if (resume) {
    energy_control.LoadCheckpoint(resume);
    resume->ExpectEnd();
  }

  const double nominal = settings.time_step;
  const double min_step = settings.smallest_step();
  const double end = settings.end_time;
  const double time_eps = 1e-9 * nominal;
  // The next checkpoint is at t₀ + k · every: the first after the state (a continued run may
  // take them at another interval than the run it continues).
  long checkpoint_count =
      checkpoints.every > 0.0
          ? static_cast<long>(std::floor((state->t - at.start + time_eps) / checkpoints.every)) + 1
          : 0;
  const auto write_checkpoint = [&] {
    ArchiveWriter out;
    SaveState(*state, &out);
    at.Save(&out);
    SaveCheckpoint(result, &out);
    integrator.SaveCheckpoint(&out);
    energy.SaveCheckpoint(&out);
    energy_control.SaveCheckpoint(&out);
    checkpoints.write(*state, out.bytes());
  };
  const bool can_fail = CanFail(model);
  while (state->t < end - time_eps) {
    double h = std::min(at.step, end - state->t);
    if (output_interval > 0.0) h = std::min(h, at.next_output - state->t);
    const StepOutcome outcome = integrator.Step(h, state);
    result.statistics.newton_iterations += outcome.newton_iterations;
    result.statistics.jacobian_updates += outcome.jacobian_updates;
    result.statistics.pattern_rebuilds += outcome.pattern_rebuilds;
    if (!outcome.accepted) {
      ++result.statistics.step_cuts;
      ++result.statistics.step_cut_reasons[StepCutReason(outcome.failure)];
      at.accepted_in_a_row = 0;
      at.step = 0.5 * h;
      if (at.step < min_step) {
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
    if (output_interval > 0.0 && std::abs(state->t - at.next_output) <= time_eps)
      state->t = at.next_output;
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
    if (step) step(*state);
    const double cut = energy_control.Cut(h, energy.account());
    if (cut < 1.0) {
      // A power-of-two fraction of the nominal step, so that the step (and with it the
      // iteration matrix, which depends on h) changes seldom.
      at.step = std::max(nominal * std::exp2(std::floor(std::log2(cut * h / nominal))), min_step);
      at.accepted_in_a_row = 0;
    } else if (!energy_control.may_grow()) {
      at.accepted_in_a_row = 0;
    } else if (++at.accepted_in_a_row >= kStepsBeforeGrowth && at.step < nominal) {
      at.step = std::min(2.0 * at.step, nominal);
      at.accepted_in_a_row = 0;
    }
    const bool at_output = output_interval <= 0.0 || state->t >= at.next_output - time_eps ||
                           state->t >= end - time_eps;
    if (at_output) {
      if (!EmitOutput(output, *state, energy.account(), &result)) return result;
      if (output_interval > 0.0)
        while (at.next_output <= state->t + time_eps)
          at.next_output = at.start + static_cast<double>(++at.output_count) * output_interval;
    }
    if (checkpoints.every > 0.0) {
      // The checkpoint of an interrupt is taken before its extra output, which a continued run
      // must not repeat.
      const auto checkpoint_time = [&] {
        return at.start + static_cast<double>(checkpoint_count) * checkpoints.every;
      };
      const bool due = state->t >= checkpoint_time() - time_eps;
      while (state->t >= checkpoint_time() - time_eps) ++checkpoint_count;
      if (due || InterruptRequested()) write_checkpoint();
    }
    if (StopIfInterrupted(output, *state, energy.account(), at_output, &result)) return result;
  }
  return result;
}

}  // namespace

SolveResult SolveDynamic(const Model& model, const DynamicSettings& settings,
                         double output_interval, const OutputCallback& output, State* state,
                         const TimeLoopCheckpoints& checkpoints, const StepCallback& step) {
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
      return RunTimeLoop(model, settings, output_interval, output, checkpoints, step, integrator,
                         state);
    }
    case IntegratorType::kImplicitMidpoint: {
      ImplicitMidpointIntegrator integrator(model, settings);
      return RunTimeLoop(model, settings, output_interval, output, checkpoints, step, integrator,
                         state);
    }
    case IntegratorType::kGeneralizedAlpha:
      break;
  }
  GeneralizedAlphaIntegrator integrator(model, settings);
  return RunTimeLoop(model, settings, output_interval, output, checkpoints, step, integrator,
                     state);
}

}  // namespace ancfnet
