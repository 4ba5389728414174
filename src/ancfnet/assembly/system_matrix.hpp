#pragma once
/// @file A sparse matrix over the unknowns whose pattern is built once from the couplings of the
/// model, with precomputed maps from each coupling's dense block to the stored values.

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// The couplings are groups of 3-coordinate blocks whose coordinates interact: each cable element
/// (its blocks r_A, r'_A, r_B, r'_B), each point mass (one block), each spring-damper link
/// (the blocks of its first point, then of its second), each rigid body (x, ψ), each body
/// attachment (the blocks of its point, then the body's x and ψ), and the contact couplings added
/// while the model moves (the blocks of one owner, an element or a point mass, then of the other).
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
  /// Owners of contact couplings: element e is owner e, point mass m is owner
  /// num_elements + m, rigid body b is BodyOwner(b). Adds a coupling group for every pair of owners (a, b) not yet coupled
  /// (a = b is allowed) and rebuilds the pattern; returns true when it changed, which makes any
  /// factorisation of the old pattern invalid. Couplings are never removed.
  bool AddContactCouplings(const std::vector<std::pair<Index, Index>>& owners);
  /// The owner of rigid body b's blocks (x, ψ) in contact couplings.
  Index BodyOwner(Index b) const { return num_elements_ + num_point_masses_ + num_links_ + b; }
  /// Index of the coupling of owners (a, b) with a ≤ b, or −1. Its blocks are a's then b's.
  int FindContactCoupling(Index a, Index b) const;
  /// Adds scale · block to the 3×3 block (row block i, column block j) of contact coupling c.
  void AddContactBlock(int coupling, int i, int j, const Matrix3d& block, double scale = 1.0);
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
  // The pattern and the slots of every group from group_blocks_.
  void Rebuild();

  const DofMap* dofs_;
  std::vector<std::vector<Index>> group_blocks_;  // first coordinate of each block, per group
  std::size_t num_model_groups_ = 0;              // groups before the contact couplings
  std::unordered_map<std::uint64_t, int> contact_coupling_;  // (a, b) packed → coupling
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
