#pragma once
/// @file Numbering of the unknowns: the free coordinates of a model, in increasing order.

#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;

/// Maps global coordinates to unknowns. Fixed coordinates are eliminated (their values stay
/// prescribed); Lagrange multipliers of future joints would be numbered after the free ones.
class DofMap {
 public:
  /// Every non-fixed coordinate of the model is an unknown.
  static DofMap FreeCoordinates(const Model& model);
  /// Every coordinate is an unknown (for the full mass matrix).
  static DofMap AllCoordinates(const Model& model);

  Index num_unknowns() const { return static_cast<Index>(free_dofs_.size()); }
  Index num_coordinates() const { return static_cast<Index>(coordinate_to_unknown_.size()); }
  /// Unknown of a global coordinate, or −1 when the coordinate is fixed.
  Index unknown(Index coordinate) const { return coordinate_to_unknown_[coordinate]; }
  /// Global coordinate of each unknown.
  const std::vector<Index>& coordinates() const { return free_dofs_; }
  /// Fixed coordinates that move (model/prescribed_motion.hpp).
  const std::vector<Index>& prescribed_coordinates() const { return prescribed_dofs_; }

  /// unknowns = full[coordinates()] (no allocation when `unknowns` has the right size).
  void Restrict(const VectorXd& full, VectorXd* unknowns) const;
  /// full[coordinates()] += scale · unknowns.
  void AddExpanded(const VectorXd& unknowns, double scale, VectorXd* full) const;

 private:
  DofMap(const Model& model, bool eliminate_fixed);
  std::vector<Index> coordinate_to_unknown_;
  std::vector<Index> free_dofs_;
  std::vector<Index> prescribed_dofs_;
};

}  // namespace ancfnet
