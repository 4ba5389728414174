#pragma once
/// @file Reads the `bodies` and `attachments` lists of a scene (model/rigid_body.hpp):
///   bodies: [{name, mass, inertia: [J1, J2, J3] | [[..], [..], [..]], position,
///             orientation: {matrix: [[..], [..], [..]]} | {axis, angle}
///                        | {quaternion: [w, x, y, z]},
///             velocity, angular_velocity, angular_velocity_frame: body | world,
///             motion: free | fixed | prescribed}]
///   attachments: [{name, body, point: POINT, body_point: [sx, sy, sz], stiffness, damping}]

#include <functional>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// Adds one body; InputError with file, line and key on any mistake.
void ReadRigidBody(const YamlValue& item, ModelBuilder* builder);

/// Adds one attachment; its point is read by `read_point` (the scene's POINT forms). Without a
/// stiffness it is a fixed one, whose penalty stiffness comes from `time_step` (s).
void ReadBodyAttachment(const YamlValue& item,
                        const std::function<CablePointRef(const YamlValue&)>& read_point,
                        double time_step, ModelBuilder* builder);

}  // namespace ancfnet
