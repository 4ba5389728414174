#pragma once
/// @file Ideal joints (the description): holonomic constraints g(q) = 0 between two anchors
/// (model/clearance_joint.hpp: the ground, a rigid body, a point mass or an ANCF material point),
/// enforced exactly by Lagrange multipliers (forces/joint_constraints.hpp). docs/theory.md,
/// "Ideal joints".

#include <string>

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/clearance_joint.hpp"

namespace ancfnet {

/// A spherical, revolute, weld, line or prismatic joint between `first` and `second`.
struct IdealJoint {
  enum class Type {
    kSpherical,  ///< the two centres coincide: c₁ − c₂ = 0 (3 equations)
    kRevolute,   ///< spherical, and the first's axis stays normal to two directions fixed in the
                 ///< second: (R₁ u)·(R₂ w_k) = 0, k = 1, 2 (5 equations; the second side the
                 ///< ground or a body, the first too or a cable point, whose axis is then its
                 ///< slope r': r'·(R₂ w_k) = 0)
    kWeld,       ///< a cable point fixed to the second: its centre and its slope r' = R₂ t
                 ///< follow the second (6 equations)
    kLine,       ///< the first's centre stays on the line through the second's centre along
                 ///< the axis: (c₁ − c₂)·(R₂ w_k) = 0, k = 1, 2 (2 equations)
    kPrismatic,  ///< line, and the orientations locked: (R₁ u)·(R₂ w₁) = (R₁ u)·(R₂ w₂) =
                 ///< (R₁ v)·(R₂ w₂) = 0 (5 equations; body or ground each side)
  };
  std::string name;
  Type type = Type::kSpherical;
  JointAnchor first;
  JointAnchor second;
  /// kRevolute, kPrismatic: the axis u in the first's frame (unit; the world frame for the
  /// ground).
  Vector3d axis_in_first = Vector3d::UnitZ();
  /// kPrismatic: v, the direction of w₁ at t = 0, in the first's frame.
  Vector3d normal1_in_first = Vector3d::UnitX();
  /// kRevolute, kLine, kPrismatic: two unit directions w₁, w₂ normal to the axis, in the
  /// second's frame.
  Vector3d normal1_in_second = Vector3d::UnitX();
  Vector3d normal2_in_second = Vector3d::UnitY();
  /// kWeld: the cable's slope t at t = 0 in the second's frame (not normalised: its length is
  /// the stretch of the slope, which the weld keeps).
  Vector3d slope_in_second = Vector3d::UnitX();

  /// Number of constraint equations (rows of g).
  int num_equations() const {
    switch (type) {
      case Type::kSpherical:
        return 3;
      case Type::kRevolute:
        return 5;
      case Type::kWeld:
        return 6;
      case Type::kLine:
        return 2;
      case Type::kPrismatic:
        return 5;
    }
    return 0;
  }
};

}  // namespace ancfnet
