#include "ancfnet/contact/broad_phase/uniform_grid.hpp"

#include <gtest/gtest.h>

#include <random>

namespace ancfnet {
namespace {

std::vector<std::pair<int, int>> BruteForce(const std::vector<Aabb>& boxes) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j)
      if (boxes[i].Overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

// Random capsules of mixed sizes in a cube, some far outside it: the grid finds exactly the
// overlapping pairs of the O(N²) test, each once.
TEST(UniformGridBroadPhase, FindsExactlyTheOverlappingPairs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> position(-1.0, 1.0), length(0.0, 0.2);
  UniformGridBroadPhase grid;
  std::vector<std::pair<int, int>> pairs;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Aabb> boxes;
    const int n = 50 + 40 * trial;
    for (int k = 0; k < n; ++k) {
      const Vector3d a(position(rng), position(rng), position(rng));
      const Vector3d b = a + length(rng) * Vector3d(position(rng), position(rng), position(rng));
      boxes.push_back(Aabb::OfCapsule(k % 17 == 0 ? a * 100.0 : a, k % 17 == 0 ? b * 100.0 : b,
                                      0.01, 0.005 * (k % 3)));
    }
    grid.FindOverlaps(boxes, &pairs);
    const auto expected = BruteForce(boxes);
    ASSERT_EQ(pairs, expected) << "trial " << trial;
    if (trial == 19) {
      EXPECT_GT(expected.size(), 100u);
    }
  }
}

TEST(UniformGridBroadPhase, DegenerateInput) {
  UniformGridBroadPhase grid;
  std::vector<std::pair<int, int>> pairs{{0, 1}};
  grid.FindOverlaps({}, &pairs);
  EXPECT_TRUE(pairs.empty());
  // Coincident points (zero-size boxes) overlap.
  const Aabb point = Aabb::OfCapsule(Vector3d(1, 2, 3), Vector3d(1, 2, 3), 0.0, 0.0);
  grid.FindOverlaps({point, point, point}, &pairs);
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
}

}  // namespace
}  // namespace ancfnet
