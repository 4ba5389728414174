#include "ancfnet/solvers/solve_result.hpp"

#include <fmt/format.h>

#include <cmath>
#include <csignal>
#include <regex>

#include "ancfnet/common/error.hpp"
#include "ancfnet/common/interrupt.hpp"

namespace ancfnet {

bool EmitOutput(const OutputCallback& output, const State& state, const EnergyAccount& energy,
                SolveResult* result) {
  try {
    output(state, energy);
    return true;
  } catch (const SolverError& e) {
    result->completed = false;
    result->message = fmt::format("stopped at t = {:.9g}: {}", e.time(), e.what());
    return false;
  }
}

bool StopIfInterrupted(const OutputCallback& output, const State& state,
                       const EnergyAccount& energy, bool written, SolveResult* result) {
  const int signal = InterruptRequested();
  if (signal == 0) return false;
  if (!written && !EmitOutput(output, state, energy, result)) return true;
  const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
  result->completed = false;
  result->interrupted = true;
  result->message = fmt::format("interrupted by {} ({}) at t = {:.9g}", name, signal, state.t);
  return true;
}

void SaveCheckpoint(const SolveResult& result, ArchiveWriter* out) {
  const SolveStatistics& s = result.statistics;
  for (long n : {s.steps, s.newton_iterations, s.jacobian_updates, s.step_cuts,
                 s.pattern_rebuilds})
    out->Write(n);
  out->Write(s.max_constraint_violation);
  out->Write(static_cast<std::uint64_t>(s.step_cut_reasons.size()));
  for (const auto& [reason, count] : s.step_cut_reasons) {
    out->Write(reason);
    out->Write(count);
  }
  out->WriteSequence(result.failures, [](ArchiveWriter& w, const FailureEvent& event) {
    w.Write(event.time);
    w.Write(event.what);
    w.Write(event.tension);
  });
}

void LoadCheckpoint(ArchiveReader* in, SolveResult* result) {
  SolveStatistics& s = result->statistics;
  for (long* n : {&s.steps, &s.newton_iterations, &s.jacobian_updates, &s.step_cuts,
                  &s.pattern_rebuilds})
    *n = in->Read<long>();
  s.max_constraint_violation = in->Read<double>();
  s.step_cut_reasons.clear();
  // Read one by one: a damaged count ends at the end of the payload.
  for (auto n = in->Read<std::uint64_t>(); n > 0; --n) {
    std::string reason = in->ReadString();
    s.step_cut_reasons[reason] = in->Read<long>();
  }
  in->ReadSequence(&result->failures, 3 * sizeof(double), [](ArchiveReader& r, FailureEvent* e) {
    e->time = r.Read<double>();
    e->what = r.ReadString();
    e->tension = r.Read<double>();
  });
}

std::string StepCutReason(const std::string& failure) {
  static const std::regex kNumber(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  return std::regex_replace(failure, kNumber, "#");
}

VectorXd CalcIncrementWeights(const VectorXd& coordinate_scales,
                              const std::vector<Index>& coordinates, double rtol, double atol) {
  VectorXd weights(static_cast<Index>(coordinates.size()));
  for (Index i = 0; i < weights.size(); ++i)
    weights[i] = atol + rtol * coordinate_scales[coordinates[i]];
  return weights;
}

double CalcResidualWork(const VectorXd& q, const VectorXd& q_start,
                        const std::vector<Index>& coordinates, const VectorXd& r) {
  double work = 0.0;
  for (std::size_t i = 0; i < coordinates.size(); ++i)
    work += (q[coordinates[i]] - q_start[coordinates[i]]) * r[static_cast<Index>(i)];
  return std::abs(work);
}

double WeightedRmsNorm(const Eigen::Ref<const VectorXd>& dx, const VectorXd& weights,
                       double scale) {
  if (dx.size() == 0) return 0.0;
  return std::abs(scale) * (dx.array() / weights.array()).matrix().norm() /
         std::sqrt(static_cast<double>(dx.size()));
}

}  // namespace ancfnet
