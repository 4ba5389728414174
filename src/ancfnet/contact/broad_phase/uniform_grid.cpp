#include "ancfnet/contact/broad_phase/uniform_grid.hpp"

#include <algorithm>
#include <cmath>

namespace ancfnet {
namespace {

// 21 bits per axis, offset so that cells −2²⁰ … 2²⁰ − 1 are packed without sign.
constexpr std::int64_t kOffset = std::int64_t{1} << 20;
constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;

std::uint64_t PackCell(std::int64_t i, std::int64_t j, std::int64_t k) {
  return (static_cast<std::uint64_t>((i + kOffset) & kMask) << 42) |
         (static_cast<std::uint64_t>((j + kOffset) & kMask) << 21) |
         static_cast<std::uint64_t>((k + kOffset) & kMask);
}

}  // namespace

void UniformGridBroadPhase::FindOverlaps(const std::vector<Aabb>& boxes,
                                         std::vector<std::pair<int, int>>* pairs, double min_cell) {
  pairs->clear();
  if (boxes.size() < 2) return;
  Vector3d low = boxes[0].min;
  double cell = min_cell;
  for (const Aabb& b : boxes) {
    low = low.cwiseMin(b.min);
    cell = std::max(cell, (b.max - b.min).maxCoeff());
  }
  // Cells are counted from the lowest corner; wider scenes than 2²¹ cells wrap, which only
  // adds candidate pairs that the overlap test then rejects.
  auto cell_of = [&](double x, double x0) {
    return static_cast<std::int64_t>(std::floor((x - x0) / cell));
  };
  entries_.clear();
  for (std::size_t n = 0; n < boxes.size(); ++n) {
    const Aabb& b = boxes[n];
    const std::int64_t i0 = cell_of(b.min.x(), low.x()), i1 = cell_of(b.max.x(), low.x());
    const std::int64_t j0 = cell_of(b.min.y(), low.y()), j1 = cell_of(b.max.y(), low.y());
    const std::int64_t k0 = cell_of(b.min.z(), low.z()), k1 = cell_of(b.max.z(), low.z());
    for (std::int64_t i = i0; i <= i1; ++i)
      for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t k = k0; k <= k1; ++k)
          entries_.push_back({PackCell(i, j, k), static_cast<int>(n)});
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.key != b.key ? a.key < b.key : a.box < b.box;
  });
  for (std::size_t first = 0; first < entries_.size();) {
    std::size_t last = first;
    while (last < entries_.size() && entries_[last].key == entries_[first].key) ++last;
    for (std::size_t a = first; a < last; ++a) {
      const Aabb& ba = boxes[entries_[a].box];
      for (std::size_t b = a + 1; b < last; ++b) {
        const Aabb& bb = boxes[entries_[b].box];
        if (!ba.Overlaps(bb)) continue;
        // Report the pair only in the cell holding the lowest corner of the overlap, so that
        // boxes sharing several cells give it once.
        const Vector3d corner = ba.min.cwiseMax(bb.min);
        if (PackCell(cell_of(corner.x(), low.x()), cell_of(corner.y(), low.y()),
                     cell_of(corner.z(), low.z())) != entries_[first].key)
          continue;
        pairs->emplace_back(entries_[a].box, entries_[b].box);
      }
    }
    first = last;
  }
  std::sort(pairs->begin(), pairs->end());
}

}  // namespace ancfnet
