#pragma once
/// @file A sparse matrix over the unknowns whose pattern is built once from the couplings of the
/// model, with precomputed maps from each coupling's dense block to the stored values.

#include <vector>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// The couplings are groups of 3-coordinate blocks whose coordinates interact: each cable element
/// (its blocks r_A, r'_A, r_B, r'_B), each point mass (one block), and each spring-damper link
/// (the blocks of its first point, then of its second), each rigid body (x, ψ) and each body
/// attachment (the blocks of its point, then the body's x and ψ).
class SystemMatrix {
 public:
  /// Pattern of the model's couplings between unknowns of `dofs`; values zero.
  SystemMatrix(const Model& model, const DofMap& dofs);

  const SparseMatrixd& matrix() const { return matrix_; }
  void SetZero();
  /// Adds scale · block to the entries of cable element `element` (rows/columns of fixed
  /// coordinates are skipped). No search, no allocation.
  void AddElementBlock(Index element, const Matrix12d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 diagonal block of point mass `point`.
  void AddPointMassBlock(Index point, const Matrix3d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block (row block i, column block j) of link `link`, its
  /// blocks numbered first point's then second point's.
  void AddLinkBlock(Index link, int i, int j, const Matrix3d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block (i, j) of rigid body `body` (0: x, 1: ψ).
  void AddBodyBlock(Index body, int i, int j, const Matrix3d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block (i, j) of body attachment `attachment`, its blocks
  /// numbered the point's, then the body's x and ψ.
  void AddAttachmentBlock(Index attachment, int i, int j, const Matrix3d& block,
                          double scale = 1.0);
  /// Adds scale · block to the 3×3 block of rows starting at coordinate `row`, columns at `col`
  /// (both inside one coupling group). Searches the pattern: for rare terms only.
  void AddBlock3(Index row, Index col, const Matrix3d& block, double scale = 1.0);

 private:
  struct Group {
    int num_blocks = 0;
    std::size_t first_slot = 0;  // slots of entry (i, j) at first_slot + 3 num_blocks j + i
  };
  void AddGroupBlock(const Group& group, int i, int j, const Matrix3d& block, double scale);

  const DofMap* dofs_;
  SparseMatrixd matrix_;
  std::vector<Group> groups_;  // elements, point masses, links, bodies, then attachments
  Index num_elements_ = 0;
  Index num_point_masses_ = 0;
  Index num_links_ = 0;
  Index num_bodies_ = 0;
  // Index in matrix_.valuePtr() of each group entry, or −1 when its row or column is fixed.
  std::vector<int> slot_;
};

}  // namespace ancfnet
