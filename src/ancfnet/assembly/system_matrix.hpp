#pragma once
/// @file A sparse matrix over the unknowns whose pattern is built once from the element
/// connectivity, with precomputed maps from each element's 12×12 block to the stored values.

#include <vector>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

class SystemMatrix {
 public:
  /// Pattern of all element couplings between unknowns of `dofs`, values zero.
  SystemMatrix(const Model& model, const DofMap& dofs);

  const SparseMatrixd& matrix() const { return matrix_; }
  void SetZero();
  /// Adds scale · block to the entries of element `element` (rows/columns of fixed coordinates
  /// are skipped). No search, no allocation.
  void AddElementBlock(Index element, const Matrix12d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block of rows starting at coordinate `row`, columns at `col`
  /// (both inside one element's coordinates).
  void AddBlock3(Index row, Index col, const Matrix3d& block, double scale = 1.0);

 private:
  const DofMap* dofs_;
  SparseMatrixd matrix_;
  // For element e, slot_[144 e + 12 j + i] is the index in matrix_.valuePtr() of entry (i, j) of
  // its block, or −1 when row or column is fixed.
  std::vector<int> slot_;
};

}  // namespace ancfnet
