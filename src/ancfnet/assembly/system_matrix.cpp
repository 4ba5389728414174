#include "ancfnet/assembly/system_matrix.hpp"

#include <cassert>

#include "ancfnet/model/model.hpp"

namespace ancfnet {
namespace {

// Index of entry (row, col) in the compressed storage of a column-major matrix.
int FindSlot(const SparseMatrixd& m, Index row, Index col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, static_cast<int>(row));
  assert(it != end && *it == row);
  return static_cast<int>(it - m.innerIndexPtr());
}

}  // namespace

SystemMatrix::SystemMatrix(const Model& model, const DofMap& dofs) : dofs_(&dofs) {
  const auto& elements = model.elements();
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(elements.size() * kCableElementDofs * kCableElementDofs);
  for (const CableElement& element : elements)
    for (Index c : element.dofs)
      for (Index r : element.dofs)
        if (dofs.unknown(r) >= 0 && dofs.unknown(c) >= 0)
          triplets.emplace_back(dofs.unknown(r), dofs.unknown(c), 0.0);
  matrix_.resize(dofs.num_unknowns(), dofs.num_unknowns());
  matrix_.setFromTriplets(triplets.begin(), triplets.end());
  matrix_.makeCompressed();

  slot_.assign(elements.size() * kCableElementDofs * kCableElementDofs, -1);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (int j = 0; j < kCableElementDofs; ++j)
      for (int i = 0; i < kCableElementDofs; ++i) {
        const Index r = dofs.unknown(elements[e].dofs[i]);
        const Index c = dofs.unknown(elements[e].dofs[j]);
        if (r >= 0 && c >= 0) slot_[144 * e + 12 * j + i] = FindSlot(matrix_, r, c);
      }
}

void SystemMatrix::SetZero() {
  std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

void SystemMatrix::AddElementBlock(Index element, const Matrix12d& block, double scale) {
  double* values = matrix_.valuePtr();
  const int* slots = slot_.data() + 144 * element;
  for (int j = 0; j < kCableElementDofs; ++j)
    for (int i = 0; i < kCableElementDofs; ++i)
      if (slots[12 * j + i] >= 0) values[slots[12 * j + i]] += scale * block(i, j);
}

void SystemMatrix::AddBlock3(Index row, Index col, const Matrix3d& block, double scale) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const Index r = dofs_->unknown(row + i);
      const Index c = dofs_->unknown(col + j);
      if (r >= 0 && c >= 0) matrix_.valuePtr()[FindSlot(matrix_, r, c)] += scale * block(i, j);
    }
}

}  // namespace ancfnet
