// The narrow phase of a thread's capsule against each kind of rigid target
// (CalcSegmentTargetDistance: samples plus a safeguarded Newton search along the axis), against
// the point query of an inspection sphere (CalcPointTargetDistance) on the same targets. The
// targets are about 0.1 m across; the 8 mm segments (a capsule of 8 radii of a 2 mm thread) lie
// within 5 mm of the surface, in random directions. The mesh is an icosphere of 1280 or 20480
// triangles. Counter `queries`: point queries per segment. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <vector>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/contact/target_distance.hpp"

namespace ancfnet {
namespace {

ContactTarget MakeTarget(int kind) {
  ContactTarget t;
  t.kind = static_cast<ContactTarget::Kind>(kind < 5 ? kind : 5);
  t.radius = 0.05;
  t.half_length = 0.05;
  t.normal = Vector3d(0.2, 1.0, 0.1).normalized();
  t.half_extents = Vector3d(0.05, 0.04, 0.03);
  t.rotation = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  if (t.kind == ContactTarget::Kind::kPlane) t.normal = Vector3d::UnitZ();
  if (kind >= 5) t.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.05, kind == 5 ? 3 : 5));
  return t;
}

// Segments whose midpoints lie 0 … 5 mm off the surface (moved along the normal of a random
// point 0.06 m from the centre), of length 8 mm.
std::vector<std::pair<Vector3d, Vector3d>> Segments(const ContactTarget& target) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> gap(0.0, 0.005);
  std::vector<std::pair<Vector3d, Vector3d>> segments(1024);
  for (auto& [a, b] : segments) {
    Vector3d p = 0.06 * Vector3d(g(rng), g(rng), g(rng)).normalized();
    const TargetDistance d = CalcPointTargetDistance(target, p);
    p += (gap(rng) - d.distance) * d.normal;
    const Vector3d u = Vector3d(g(rng), g(rng), g(rng)).normalized();
    a = p - 0.004 * u;
    b = p + 0.004 * u;
  }
  return segments;
}

// range(0): the target kind (ContactTarget::Kind order, 5: mesh of 1280, 6: of 20480 triangles).
void BM_CapsuleTarget(benchmark::State& state) {
  const ContactTarget target = MakeTarget(static_cast<int>(state.range(0)));
  const auto segments = Segments(target);
  std::size_t i = 0;
  double queries = 0.0;
  for (auto _ : state) {
    const auto& [a, b] = segments[i++ % segments.size()];
    const SegmentTargetDistance d = CalcSegmentTargetDistance(target, a, b);
    queries += d.evaluations;
    benchmark::DoNotOptimize(d.distance);
  }
  state.counters["queries"] = benchmark::Counter(queries, benchmark::Counter::kAvgIterations);
}

void BM_SphereTarget(benchmark::State& state) {
  const ContactTarget target = MakeTarget(static_cast<int>(state.range(0)));
  const auto segments = Segments(target);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b] = segments[i++ % segments.size()];
    benchmark::DoNotOptimize(CalcPointTargetDistance(target, 0.5 * (a + b)).distance);
  }
}

BENCHMARK(BM_CapsuleTarget)->Name("CapsuleTargetQuery")->DenseRange(0, 6)->ArgName("kind");
BENCHMARK(BM_SphereTarget)->Name("SphereTargetQuery")->DenseRange(0, 6)->ArgName("kind");

}  // namespace
}  // namespace ancfnet
