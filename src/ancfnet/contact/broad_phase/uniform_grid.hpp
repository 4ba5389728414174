#pragma once
/// @file Broad phase by uniform-grid hashing: the pairs of boxes that overlap, found by sorting
/// the (cell, box) entries of every box's cells and testing the boxes that share a cell. Cost
/// O(N log N) for N boxes of similar size (the sort; a cell holds O(1) boxes), against the O(N²)
/// of testing every pair. Chosen over a dynamic AABB tree because the primitives of a net are
/// alike in size and all move every step, so the grid needs no refitting or rebalancing and its
/// storage is sized once (docs/theory.md, "Self-contact", and docs/benchmarks.md).

#include <cstdint>
#include <utility>
#include <vector>

#include "ancfnet/contact/broad_phase/aabb.hpp"

namespace ancfnet {

class UniformGridBroadPhase {
 public:
  /// Fills `pairs` with every (i, j), i < j, whose boxes overlap, each pair once, in increasing
  /// order. The cell edge is the largest box extent (so a box spans at most 2 cells per axis),
  /// at least `min_cell` (m). Storage grows to its largest size once and is then reused.
  void FindOverlaps(const std::vector<Aabb>& boxes, std::vector<std::pair<int, int>>* pairs,
                    double min_cell = 1e-9);

 private:
  struct Entry {
    std::uint64_t key;  // cell coordinates packed, sorted on
    int box;
  };
  std::vector<Entry> entries_;
};

}  // namespace ancfnet
