#pragma once
/// @file The constraint equations g(q) = 0 of the ideal joints (model/ideal_joint.hpp), their
/// Jacobian G = ∂g/∂q, the reaction Gᵀλ of the multipliers λ with its geometric stiffness
/// ∂(Gᵀλ)/∂q, the convective term Ġv of g̈ = G a + Ġv, and the bordered matrix [S Gᵀ; G 0]
/// the static solver and generalised-α factorise. Each joint is made of three kinds of equation
/// on its anchors' motions (forces/joint_anchor.hpp; a body turns as δR = R δψ̃), its rows in
/// this order:
///   coincidence   c₁ − c₂ = 0                  (spherical, revolute, weld)
///   in-plane      (c₁ − c₂)·(R₂ w) = 0         (line, prismatic: w₁, w₂)
///   perpendicular (R₁ u)·(R₂ w) = 0            (revolute: the axis u against w₁, w₂;
///                                               prismatic: the same and v against w₂;
///                                               r'·(R₂ w) for a revolute on a cable point)
///   slope         r'₁ − R₂ t = 0               (weld)
/// Géradin & Cardona (2001); Bauchau (2011). docs/theory.md, "Ideal joints".

#include <array>
#include <vector>

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/joint_anchor.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// What an ideal joint applies to its second side (world axes): the force (N) and its moment
/// about the second side's centre c₂ (N m), from the multipliers λ; the first side receives the
/// opposite force (about c₂ the opposite moment too).
struct JointReaction {
  Vector3d force = Vector3d::Zero();
  Vector3d moment = Vector3d::Zero();
};

class JointConstraints {
 public:
  explicit JointConstraints(const Model& model);

  /// Number of equations m (= Model::num_constraint_equations()).
  Index size() const { return static_cast<Index>(violation_.size()); }
  bool empty() const { return violation_.size() == 0; }

  /// g, G and Ġv at (q, v); a body's pose uses its reference rotation in `rotation`.
  void Evaluate(const VectorXd& q, const VectorXd& v, const std::vector<Matrix3d>& rotation);
  /// g at the last Evaluate (m for a position equation, 1 for a direction or slope equation).
  const VectorXd& violation() const { return violation_; }
  /// Ġv at the last Evaluate: g̈ = G a + Ġv.
  const VectorXd& convective_term() const { return convective_; }
  /// max_i |g_i|, 0 without joints.
  double MaxViolation() const;
  /// max_i |g_i| / (atol + rtol L_i), L_i the distance of a position equation's points from the
  /// origin (1 for direction equations): ≤ 1 when g is as small as Newton's tolerances ask of
  /// the coordinates.
  double ScaledViolation(double rtol, double atol) const;

  /// ġ = G v at the last Evaluate's q (v over all coordinates).
  VectorXd CalcRate(const VectorXd& v) const;
  /// The reaction of joint `joint` for the multipliers λ at the last Evaluate: −Gᵀλ on the
  /// second side, as a force and a moment about its centre c₂ (world).
  JointReaction CalcReaction(Index joint, const VectorXd& lambda) const;
  /// force += Gᵀ λ (all coordinates).
  void AddReaction(const VectorXd& lambda, VectorXd* force) const;
  /// scale · ∂(Gᵀλ)/∂q at fixed λ into the joints' couplings of `matrix`.
  void AddGeometricStiffness(const VectorXd& lambda, double scale, SystemMatrix* matrix) const;
  /// out = [S Gᵀ; G 0] over the unknowns of `dofs` (columns of fixed coordinates left out), S
  /// their (n × n) matrix, λ after the n unknowns. Its pattern does not depend on the values.
  void AssembleBorderedMatrix(const SparseMatrixd& s, const DofMap& dofs, SparseMatrixd* out);
  /// The gradient of equation `row` on block k of its joint (first anchor's blocks, then the
  /// second's) and the first coordinate of that block; for tests and probes.
  const Vector3d& Gradient(Index row, int k) const { return rows_[row].gradient[k]; }
  Index BlockDof(Index row, int k) const;
  int NumBlocks(Index row) const;

 private:
  static constexpr int kMaxBlocks = 8;
  struct Row {
    Index joint = 0;
    std::array<Vector3d, kMaxBlocks> gradient{};
    double length_scale = 1.0;  // L_i of ScaledViolation
  };
  void EvaluateJoint(Index j, const AnchorMotion& first, const AnchorMotion& second, Index row);

  const Model& model_;
  std::vector<Index> first_row_;                  // per joint
  std::vector<std::vector<Index>> joint_blocks_;  // per joint: first coordinate of each block
  std::vector<AnchorMotion> first_motion_, second_motion_;  // per joint, at the last Evaluate
  std::vector<Row> rows_;
  VectorXd violation_;
  VectorXd convective_;
  std::vector<Eigen::Triplet<double, int>> triplets_;
};

}  // namespace ancfnet
