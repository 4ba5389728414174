// The anchor scenes of docs/benchmarks.md solved in a warm process, as Chrono's anchor figures
// time "the solve or time loop only": S1, the static cantilever with P L²/EI = 10 in one load step,
// and S2, the flexible pendulum for 1 s at h = 1 ms. Model set-up (workspace, sparsity pattern,
// symbolic factorisation) is inside the timed region; building the Model is not.

#include <benchmark/benchmark.h>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/solvers/static_solver.hpp"
#include "../tests/verification/verification_scenes.hpp"

namespace ancfnet {
namespace {

const OutputCallback kNoOutput = [](const State&, const EnergyAccount&) {};

void BM_S1StaticCantilever(benchmark::State& bench) {
  ModelBuilder builder = verification::MakeCantilever(static_cast<int>(bench.range(0)));
  builder.AddPointForce({"beam", 1.0},
                        Vector3d(0.0, 0.0, -10.0 * verification::CantileverBendingStiffness()));
  const Model model = builder.Build();
  const StaticSettings settings;  // one load step, line search as fallback
  long iterations = 0;
  for (auto _ : bench) {
    State state = MakeInitialState(model);
    const SolveResult result = SolveStatic(model, settings, kNoOutput, &state);
    iterations = result.statistics.newton_iterations;
    benchmark::DoNotOptimize(state.q.data());
  }
  bench.counters["newton_iterations"] = static_cast<double>(iterations);
}
BENCHMARK(BM_S1StaticCantilever)->ArgName("elements")->Arg(4)->Arg(8)->Arg(16)
    ->Unit(benchmark::kMillisecond);

void BM_S2Pendulum(benchmark::State& bench) {
  const Model model = verification::MakePendulum(static_cast<int>(bench.range(0)));
  DynamicSettings settings;  // ρ∞ = 0.8, h = 1 ms, 1 s, adaptive Jacobian
  long iterations = 0;
  for (auto _ : bench) {
    State state = MakeInitialState(model);
    const SolveResult result = SolveDynamic(model, settings, 0.01, kNoOutput, &state);
    iterations = result.statistics.newton_iterations;
    benchmark::DoNotOptimize(state.q.data());
  }
  bench.counters["newton_iterations"] = static_cast<double>(iterations);
}
BENCHMARK(BM_S2Pendulum)->ArgName("elements")->Arg(8)->Arg(32)->Arg(128)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ancfnet
