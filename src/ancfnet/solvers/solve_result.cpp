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
