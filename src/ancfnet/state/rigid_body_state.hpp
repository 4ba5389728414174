#pragma once
/// @file The rigid bodies in a State: the pose of a body from the state's coordinates and its
/// reference rotation (State::body_rotation), and the rebasing of those reference rotations
/// after an accepted step (model/rigid_body_kinematics.hpp has the kinematics itself).

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Pose of body `b` of the model in `state`.
BodyPose CalcBodyPose(const Model& model, const State& state, Index b);

/// After an accepted step: R_ref ← R_ref exp(ψ̃), ψ ← 0 for every free body (ω, ω̇ are
/// body-frame and need no transport). Fixed and prescribed bodies keep R_ref = R_WB(0).
void RebaseBodyRotations(const Model& model, State* state);

}  // namespace ancfnet
