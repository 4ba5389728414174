#pragma once
/// @file Reads one ideal joint of a scene's `joints` list (model/ideal_joint_spec.hpp):
///   {name, type: spherical | revolute | weld | line | prismatic, between: [ANCHOR, ANCHOR],
///    point: [x, y, z], axis: [x, y, z] (revolute, line, prismatic; default [0, 0, 1])}
/// ANCHOR as for clearance joints (io/joint_anchor_reader.hpp). `point` places a ground or body
/// side that has no point of its own (default: the other side's cable point or point mass).

#include <functional>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// True when `type` names an ideal joint (the other joints are clearance joints).
bool IsIdealJointType(const std::string& type);

/// Adds the joint `item` describes; InputError with file, line and key on any mistake.
void ReadIdealJoint(const YamlValue& item,
                    const std::function<CablePointRef(const YamlValue&)>& read_point,
                    ModelBuilder* builder);

}  // namespace ancfnet
