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

double WeightedRmsNorm(const Eigen::Ref<const VectorXd>& dx, const VectorXd& x, const std::vector<Index>& coordinates,
                       double scale, double rtol, double atol) {
  if (dx.size() == 0) return 0.0;
  double sum = 0.0;
  for (Index i = 0; i < dx.size(); ++i) {
    const double w = atol + rtol * std::abs(x[coordinates[i]]);
    const double r = scale * dx[i] / w;
    sum += r * r;
  }
  return std::sqrt(sum / static_cast<double>(dx.size()));
}

}  // namespace ancfnet
