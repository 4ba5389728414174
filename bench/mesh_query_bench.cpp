// Closest-point queries on a triangle mesh target: the bounding-volume hierarchy's branch-and-
// bound descent against testing every triangle, on icospheres of 80, 1280 and 20480 triangles
// (k = 1, 3, 5 subdivisions). Query points uniform in the cube of side 3R around the sphere.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/mesh/mesh_bvh.hpp"

namespace ancfnet {
namespace {

std::vector<Vector3d> QueryPoints() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Vector3d> points(1024);
  for (Vector3d& p : points) p = Vector3d(u(rng), u(rng), u(rng));
  return points;
}

template <bool kBruteForce>
void BM_MeshClosestPoint(benchmark::State& state) {
  const MeshBvh bvh(MakeIcosphere(1.0, static_cast<int>(state.range(0))));
  const std::vector<Vector3d> points = QueryPoints();
  std::size_t i = 0;
  for (auto _ : state) {
    const Vector3d& p = points[i++ % points.size()];
    const MeshDistance d = kBruteForce ? bvh.CalcDistanceBruteForce(p) : bvh.CalcDistance(p);
    benchmark::DoNotOptimize(d.distance);
  }
  state.counters["triangles"] = static_cast<double>(bvh.mesh().triangles.cols());
}

BENCHMARK_TEMPLATE(BM_MeshClosestPoint, false)->Name("MeshBvhQuery")->Arg(1)->Arg(3)->Arg(5);
BENCHMARK_TEMPLATE(BM_MeshClosestPoint, true)->Name("MeshBruteForceQuery")->Arg(1)->Arg(3)->Arg(5);

}  // namespace
}  // namespace ancfnet
