#pragma once
/// @file Reads one side of a joint (model/clearance_joint_spec.hpp: JointAnchorSpec), as clearance
/// and ideal joints name it:
///   `ground` (placed by the joint) or {ground: [x, y, z]};
///   {body: NAME, point: [x, y, z]} (the point at t = 0 in world coordinates; optional);
///   a point as elsewhere in a scene (CABLE.start, CABLE.end, {cable: NAME, s: FRACTION}, a
///   point mass).

#include <functional>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// The side `value` names; `read_point` reads a cable point or point mass.
JointAnchorSpec ReadJointAnchor(const YamlValue& value,
                                const std::function<CablePointRef(const YamlValue&)>& read_point);

}  // namespace ancfnet
