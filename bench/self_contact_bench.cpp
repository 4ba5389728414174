// Google Benchmark timings of the self-contact search: the uniform-grid broad phase against the
// test of every pair, on crumpled chains of capsules at constant density (so a cell holds about
// the same number of capsules at every size, as in a net wrapping a target), and the whole
// search of a step (broad phase, exclusions, narrow phase) on flat square nets. Figures:
// docs/benchmarks.md, "Self-contact search".

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "ancfnet/contact/broad_phase/uniform_grid.hpp"
#include "ancfnet/forces/self_contact.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kRadius = 0.001, kCapsuleLength = 0.006;

// Random-walk chains of capsules filling a cube whose volume grows with their number.
std::vector<Aabb> CrumpledChains(int n) {
  std::mt19937 rng(11);
  std::normal_distribution<double> step(0.0, 1.0);
  const double side = 0.05 * std::cbrt(n / 1000.0);
  std::uniform_real_distribution<double> start(0.0, side);
  std::vector<Aabb> boxes;
  Vector3d x(start(rng), start(rng), start(rng));
  for (int k = 0; k < n; ++k) {
    if (k % 50 == 0) x = Vector3d(start(rng), start(rng), start(rng));
    Vector3d d(step(rng), step(rng), step(rng));
    Vector3d next = x + kCapsuleLength * d.normalized();
    next = next.cwiseMax(Vector3d::Zero()).cwiseMin(Vector3d::Constant(side));
    boxes.push_back(Aabb::OfCapsule(x, next, kRadius, 0.5 * kRadius));
    x = next;
  }
  return boxes;
}

void BM_UniformGrid(benchmark::State& state) {
  const std::vector<Aabb> boxes = CrumpledChains(static_cast<int>(state.range(0)));
  UniformGridBroadPhase grid;
  std::vector<std::pair<int, int>> pairs;
  for (auto _ : state) {
    grid.FindOverlaps(boxes, &pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_UniformGrid)->RangeMultiplier(4)->Range(1 << 10, 1 << 18)->Complexity();

void BM_AllPairs(benchmark::State& state) {
  const std::vector<Aabb> boxes = CrumpledChains(static_cast<int>(state.range(0)));
  std::vector<std::pair<int, int>> pairs;
  for (auto _ : state) {
    pairs.clear();
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
        if (boxes[i].Overlaps(boxes[j])) pairs.emplace_back(i, j);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_AllPairs)->RangeMultiplier(4)->Range(1 << 10, 1 << 14)->Complexity();

// The search of one step on a flat n × n square net of 1 m, 2 elements per thread.
void BM_SelfContactSearch(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  ModelBuilder builder;
  NetSpec net;
  net.name = "net";
  net.topology = MakeGridNet({.side_u = 1.0, .side_v = 1.0, .meshes_u = n, .meshes_v = n});
  net.thread = MakeRopeProperties(Material{.youngs_modulus = 1e11, .density = 970},
                                    MakeCircleSection(2 * kRadius));
  net.elements_per_thread = 2;
  AddNet(builder, net);
  ContactSpec spec;
  spec.normal = MakeHertzContactLaw(1e8);
  spec.self_contact = true;
  spec.point_mass_radius = kRadius;
  builder.SetContact(spec);
  const Model model = builder.Build();
  SelfContact contact(model);
  State s = MakeInitialState(model);
  for (Index i = 0; i < s.v.size(); ++i) s.v[i] = std::sin(0.37 * i);
  for (auto _ : state) {
    contact.FindCandidates(s, 1e-4);
    benchmark::DoNotOptimize(contact.num_candidates());
  }
  state.counters["primitives"] = static_cast<double>(contact.primitives().size());
  state.counters["candidates"] = contact.num_candidates();
}
BENCHMARK(BM_SelfContactSearch)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ancfnet
