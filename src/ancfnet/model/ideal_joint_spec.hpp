#pragma once
/// @file An ideal joint as given to ModelBuilder::AddIdealJoint (model/model_builder.hpp), with
/// its two sides named as a scene names them.

#include <optional>
#include <string>

#include "ancfnet/model/clearance_joint_spec.hpp"
#include "ancfnet/model/ideal_joint.hpp"

namespace ancfnet {

/// An ideal joint (model/ideal_joint.hpp) before its anchors are resolved.
struct IdealJointSpec {
  std::string name;
  IdealJoint::Type type = IdealJoint::Type::kSpherical;
  JointAnchorSpec first = {};
  JointAnchorSpec second = {};
  /// The joint's point at t = 0 (m, world), for a side that is the ground or a body without a
  /// position of its own. Default: the centre of a side that is a cable point or point mass.
  std::optional<Vector3d> point = std::nullopt;
  /// kRevolute, kLine, kPrismatic: the axis at t = 0 (world), non-zero (normalised when added).
  Vector3d axis = Vector3d::UnitZ();
};

}  // namespace ancfnet
