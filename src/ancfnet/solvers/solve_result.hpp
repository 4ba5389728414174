#pragma once
/// @file What an analysis reports back, and how it hands states to the outputs.

#include <functional>
#include <map>
#include <string>

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/analysis/failure.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

struct SolveStatistics {
  long steps = 0;              ///< accepted time steps or load increments
  long newton_iterations = 0;  ///< all iterations, rejected attempts included
  long jacobian_updates = 0;   ///< factorisations of the iteration matrix
  long step_cuts = 0;          ///< rejected attempts followed by a smaller step
  long pattern_rebuilds = 0;   ///< new patterns of the iteration matrix (contact couplings)
  /// Rejected attempts by reason (StepCutReason of the failure), so a user sees what cuts the step.
  std::map<std::string, long> step_cut_reasons;
  /// The largest violation max_i |g_i| of the ideal joints' constraints at an accepted step or
  /// increment (m for position equations, 1 for direction and slope equations); 0 without joints.
  double max_constraint_violation = 0.0;
};

struct SolveResult {
  SolveStatistics statistics;
  bool completed = true;
  /// Stopped on request (InterruptRequested) after writing the state reached; completed is false.
  bool interrupted = false;
  std::string message;                 ///< why the analysis stopped early
  std::vector<FailureEvent> failures;  ///< threads and connections that broke, in time order
};

/// Writes the statistics and the failures of `result` (what a run continued from a checkpoint
/// carries on counting from).
void SaveCheckpoint(const SolveResult& result, ArchiveWriter* out);
/// Reads what SaveCheckpoint wrote into `result`'s statistics and failures.
void LoadCheckpoint(ArchiveReader* in, SolveResult* result);

/// Called with the state at t = 0 (load factor 0) and at every output step. It may throw
/// SolverError when a value cannot be written (not finite): the analysis then stops.
using OutputCallback = std::function<void(const State&, const EnergyAccount&)>;

/// Calls `output`. When it throws SolverError, marks `result` failed with the reason (keeping
/// the statistics gathered so far) and returns false: the caller must stop.
bool EmitOutput(const OutputCallback& output, const State& state, const EnergyAccount& energy,
                SolveResult* result);

/// After an accepted step or load increment at `state`: when an interrupt is pending, marks
/// `result` interrupted (not completed) with a message naming the signal and the time, and
/// returns true: the caller must stop. `written` says whether `state` was already handed to
/// `output`; if not, it is handed now, so that the outputs end at the state reached.
bool StopIfInterrupted(const OutputCallback& output, const State& state,
                       const EnergyAccount& energy, bool written, SolveResult* result);

/// The kind of a step failure: its message with every number replaced by '#', so that failures
/// that differ only in where and how much count together ("no convergence in # iterations",
/// "self-contact: element # and element # passed through each other").
std::string StepCutReason(const std::string& failure);

/// The weights w_i = atol + rtol s_c(i) of WeightedRmsNorm for each unknown i, s the scales of
/// the model's coordinates (model/coordinate_scales.hpp: the model's length for positions, 1 for
/// gradients and rotations) and `coordinates` the map from unknown i to its coordinate c(i).
/// Unlike weights atol + rtol |x_i|, they do not depend on where the model sits or how it is
/// turned: a coordinate that happens to be near 0 is not held to atol alone.
VectorXd CalcIncrementWeights(const VectorXd& coordinate_scales,
                              const std::vector<Index>& coordinates, double rtol, double atol);

/// |Σ_i (q_c(i) − q₀_c(i)) r_i| (J): the work of the force rows r_i of a residual over the
/// displacement from q₀ to q of the coordinates c(i) of the unknowns (`coordinates`); rows of r
/// beyond them (constraint equations) are left out.
double CalcResidualWork(const VectorXd& q, const VectorXd& q_start,
                        const std::vector<Index>& coordinates, const VectorXd& r);

/// Weighted RMS norm √(mean_i (scale dx_i / w_i)²) over the unknowns (Hairer & Wanner 1996,
/// II.4), w from CalcIncrementWeights.
double WeightedRmsNorm(const Eigen::Ref<const VectorXd>& dx, const VectorXd& weights, double scale);

}  // namespace ancfnet
