#pragma once
/// @file Resolving a joint's side as a scene names it (JointAnchorSpec) into a JointAnchor of the
/// model, for clearance joints and ideal joints alike.

#include "ancfnet/model/clearance_joint_spec.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// The centre at t = 0 of a resolved anchor (m, world).
Vector3d CalcInitialAnchorCenter(const Model& model, const JointAnchor& anchor);

/// The anchor `spec` names: a body (its point from spec.position, default its centre of mass)
/// or a point mass or cable point; the ground's point is left for the caller. InputError
/// prefixed with `side` ("journal: no rigid body named 'x'") when the name does not resolve.
JointAnchor ResolveJointAnchor(const Model& model, const JointAnchorSpec& spec, const char* side);

}  // namespace ancfnet
