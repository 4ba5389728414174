#pragma once
/// @file A sparse matrix over the unknowns whose pattern is built once from the couplings of the
/// model, with precomputed maps from each coupling's dense block to the stored values.

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ancfnet/assembly/contact_coupling_settings.hpp"
#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/beam_shape.hpp"

namespace ancfnet {

class Model;

/// The couplings are groups of 3-coordinate blocks whose coordinates interact: each cable element
/// (its blocks r_A, r'_A, r_B, r'_B), each point mass (one block), each spring-damper link
/// (the blocks of its first point, then of its second), each rigid body (x, ψ), each body
/// attachment (the blocks of its point, then the body's x and ψ), each clearance joint (the blocks
/// of its journal's anchor, then of its bearing's), each ideal joint (its first anchor's blocks,
/// then its second's), each beam element (its eight blocks r_A, r_x,A, r_y,A, r_z,A, r_B, …; its
/// centre line is also an element group), each section lock (the r_y, r_z blocks of its first
/// node, then of its second), and the contact couplings that come and go while the
/// model moves (the blocks of one owner, an element, a point mass or a body, then of the other).
class SystemMatrix {
 public:
  /// Pattern of the model's couplings between unknowns of `dofs`; values zero.
  SystemMatrix(const Model& model, const DofMap& dofs);

  const SparseMatrixd& matrix() const { return matrix_; }
  void SetZero();
  /// Adds scale · block to the entries of cable element `element` (rows/columns of fixed
  /// coordinates are skipped). No search, no allocation.
  void AddElementBlock(Index element, const Matrix12d& block, double scale = 1.0);
  /// Adds scale · block to the entries of beam element `beam` (Model::beam_elements()).
  void AddBeamElementBlock(Index beam, const Matrix24d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 diagonal block of point mass `point`.
  void AddPointMassBlock(Index point, const Matrix3d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block (row block i, column block j) of link `link`, its
  /// blocks numbered first point's then second point's.
  void AddLinkBlock(Index link, int i, int j, const Matrix3d& block, double scale = 1.0);
  /// Owners of contact couplings: element e is owner e, point mass m is owner
  /// num_elements + m, rigid body b is BodyOwner(b). A coupling of owners (a, b) (a = b is
  /// allowed) is a group of a's blocks then b's. One update per attempted step: the couplings of
  /// `near` and `required` pairs are marked as near now. The pattern is rebuilt when a `required`
  /// pair is not coupled, or when more than settings.max_stale_fraction of the couplings are
  /// stale (not near for more than settings.keep_updates updates); a rebuild drops the stale
  /// couplings and couples every pair of both lists. Returns true when it rebuilt the pattern,
  /// which makes any factorisation of the old one invalid and renumbers the couplings. Allocates
  /// only when it rebuilds (docs/theory.md, "Contact couplings that come and go").
  bool UpdateContactCouplings(const std::vector<std::pair<Index, Index>>& required,
                              const std::vector<std::pair<Index, Index>>& near);
  /// Couples every pair of `owners` now: UpdateContactCouplings(owners, owners).
  bool AddContactCouplings(const std::vector<std::pair<Index, Index>>& owners) {
    return UpdateContactCouplings(owners, owners);
  }
  /// Retention of the contact couplings (the defaults of ContactCouplingSettings until set).
  void set_contact_coupling_settings(const ContactCouplingSettings& settings) {
    coupling_settings_ = settings;
  }
  /// Writes the contact couplings (in their order, with when each was last near) and the count
  /// of updates: what the pattern and its later updates depend on.
  void SaveContactCouplings(ArchiveWriter* out) const;
  /// Restores what SaveContactCouplings wrote and rebuilds the pattern from it (the same pattern,
  /// numbered the same). Throws InputError when an owner is not one of this model's.
  void LoadContactCouplings(ArchiveReader* in);
  /// Number of contact couplings in the pattern.
  int num_contact_couplings() const { return static_cast<int>(couplings_.size()); }
  /// Number of times the pattern was built (1 after construction).
  long num_pattern_builds() const { return num_pattern_builds_; }
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
  /// Adds scale · block to the 3×3 block (i, j) of clearance joint `joint`, its blocks numbered
  /// the journal anchor's, then the bearing anchor's (forces/joint_anchor.hpp).
  void AddClearanceJointBlock(Index joint, int i, int j, const Matrix3d& block, double scale = 1.0);
  /// The same for ideal joint `joint` (its first anchor's blocks, then its second's).
  void AddIdealJointBlock(Index joint, int i, int j, const Matrix3d& block, double scale = 1.0);
  /// Adds scale · block to the entries of section lock `lock` (Model::section_locks()), its
  /// coordinates (r_y,1, r_z,1, r_y,2, r_z,2).
  void AddSectionLockBlock(Index lock, const Matrix12d& block, double scale = 1.0);
  /// Adds scale · block to the 3×3 block of rows starting at coordinate `row`, columns at `col`
  /// (both inside one coupling group). Searches the pattern: for rare terms only.
  void AddBlock3(Index row, Index col, const Matrix3d& block, double scale = 1.0);

 private:
  struct Group {
    int num_blocks = 0;
    std::size_t first_slot = 0;  // slots of entry (i, j) at first_slot + 3 num_blocks j + i
  };
  struct ContactCoupling {
    Index a = 0, b = 0;  // owners, a ≤ b
    long last_near = 0;  // update at which its pair was last near
  };
  void AddGroupBlock(const Group& group, int i, int j, const Matrix3d& block, double scale);
  // Marks the coupling of (a, b) near; false when there is none.
  bool MarkNear(Index a, Index b);
  // Drops the stale couplings, adds those of `required` and `near` that are missing, rebuilds.
  void RebuildContactCouplings(const std::vector<std::pair<Index, Index>>& required,
                               const std::vector<std::pair<Index, Index>>& near);
  // contact_coupling_ from couplings_.
  void IndexContactCouplings();
  // The pattern and the slots of every group from group_blocks_ and couplings_.
  void Rebuild();

  const DofMap* dofs_;
  std::vector<std::vector<Index>> group_blocks_;  // first coordinate of each block, per model group
  std::vector<ContactCoupling> couplings_;
  std::unordered_map<std::uint64_t, int> contact_coupling_;  // (a, b) packed → coupling
  ContactCouplingSettings coupling_settings_;
  long num_updates_ = 0;
  long num_pattern_builds_ = 0;
  SparseMatrixd matrix_;
  std::vector<Group> groups_;  // elements, point masses, links, bodies, attachments, couplings
  Index num_elements_ = 0;
  Index num_point_masses_ = 0;
  Index num_links_ = 0;
  Index num_bodies_ = 0;
  Index num_attachments_ = 0;
  Index num_clearance_joints_ = 0;
  Index num_ideal_joints_ = 0;
  Index num_beam_elements_ = 0;
  // Index in matrix_.valuePtr() of each group entry, or −1 when its row or column is fixed.
  std::vector<int> slot_;
};

}  // namespace ancfnet
