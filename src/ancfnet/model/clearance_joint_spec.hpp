#pragma once
/// @file A clearance joint as given to ModelBuilder::AddClearanceJoint (model/model_builder.hpp),
/// with its journal and bearing named as a scene names them.

#include <optional>
#include <string>

#include "ancfnet/model/clearance_joint.hpp"

namespace ancfnet {

/// One side of a clearance joint.
struct JointAnchorSpec {
  JointAnchor::Kind kind = JointAnchor::Kind::kGround;
  /// kBody: the rigid body; kPoint: a point mass, or a cable (with `s`).
  std::string name = {};
  double s = 0.0;  ///< kPoint on a cable: the fraction of its reference length, in [0, 1]
  /// kGround, kBody: the centre at t = 0 (m, world). Default: for the ground, the other side's
  /// centre at t = 0 (a concentric start); for a body, its centre of mass.
  std::optional<Vector3d> position = std::nullopt;
};

/// A clearance joint (model/clearance_joint.hpp) before its anchors are resolved.
struct ClearanceJointSpec {
  std::string name;
  ClearanceJoint::Type type = ClearanceJoint::Type::kRevolute;
  JointAnchorSpec journal = {};
  JointAnchorSpec bearing = {};
  double clearance = 0.0;             ///< c (m), > 0
  double journal_radius = 0.0;        ///< R_J (m), > c
  Vector3d axis = Vector3d::UnitZ();  ///< kRevolute: non-zero (normalised when added)
  NormalLaw normal = {};
  std::optional<FrictionLaw> friction = std::nullopt;  ///< regularised (Ambrósio, tanh) only
};

}  // namespace ancfnet
