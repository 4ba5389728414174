// Closest-point queries on a triangle mesh target: the bounding-volume hierarchy's branch-and-
// bound descent against testing every triangle, on unit icospheres of 80, 1280 and 20480
// triangles (k = 1, 3, 5 subdivisions), for query points near the surface (|p| uniform in
// [0.9, 1.1], where contact probes are) and uniform in the cube [−1.5, 1.5]³ (points deep inside
// or far away, where the ball of radius d around p meets many boxes). Figures:
// docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/mesh/mesh_bvh.hpp"

namespace ancfnet {
namespace {

std::vector<Vector3d> QueryPoints(bool near_surface) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5), radius(0.9, 1.1);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vector3d> points(1024);
  for (Vector3d& p : points)
    p = near_surface ? Vector3d(radius(rng) * Vector3d(g(rng), g(rng), g(rng)).normalized())
                     : Vector3d(u(rng), u(rng), u(rng));
  return points;
}

// range(0): subdivisions; range(1): 1 for points near the surface, 0 for the cube.
template <bool kBruteForce>
void BM_MeshClosestPoint(benchmark::State& state) {
  const MeshBvh bvh(MakeIcosphere(1.0, static_cast<int>(state.range(0))));
  const std::vector<Vector3d> points = QueryPoints(state.range(1) == 1);
  std::size_t i = 0;
  for (auto _ : state) {
    const Vector3d& p = points[i++ % points.size()];
    const MeshDistance d = kBruteForce ? bvh.CalcDistanceBruteForce(p) : bvh.CalcDistance(p);
    benchmark::DoNotOptimize(d.distance);
  }
  state.counters["triangles"] = static_cast<double>(bvh.mesh().triangles.cols());
}

BENCHMARK_TEMPLATE(BM_MeshClosestPoint, false)
    ->Name("MeshBvhQuery")
    ->ArgsProduct({{1, 3, 5}, {1, 0}})
    ->ArgNames({"k", "near"});
BENCHMARK_TEMPLATE(BM_MeshClosestPoint, true)
    ->Name("MeshBruteForceQuery")
    ->ArgsProduct({{1, 3, 5}, {1, 0}})
    ->ArgNames({"k", "near"});

}  // namespace
}  // namespace ancfnet
