#pragma once
/// @file Reads one item of a scene's `joints` list (model/clearance_joint_spec.hpp):
///   {name, type: revolute_clearance | spherical_clearance, journal: ANCHOR, bearing: ANCHOR,
///    clearance, journal_radius, axis (revolute; default [0, 0, 1]), contact: LAW,
///    friction: FRICTION}
/// ANCHOR (io/joint_anchor_reader.hpp): `ground` (concentric with the other side at t = 0) or
/// {ground: [x, y, z]}; {body: NAME, point: [x, y, z]} (the centre at t = 0 in world
/// coordinates; default the body's centre of mass); or a cable point or point mass. LAW and FRICTION as under `contact` (law,
/// friction; io/contact_reader.hpp), friction tanh or ambrosio.

#include <functional>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// Adds the joint `item` describes; InputError with file, line and key on any mistake.
/// `read_point` reads a cable point or point mass as the scene's other keys do.
void ReadClearanceJoint(const YamlValue& item,
                        const std::function<CablePointRef(const YamlValue&)>& read_point,
                        ModelBuilder* builder);

}  // namespace ancfnet
