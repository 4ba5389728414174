#pragma once
/// @file Reads the `contact` map of a scene (contact/contact_spec.hpp):
///   law: {type: linear, stiffness, damping} | {type: hertz, stiffness, exponent}
///      | {type: hunt_crossley | lankarani_nikravesh | flores | gonthier | carvalho_martins,
///         stiffness, restitution, exponent, min_approach_speed}
///   friction: {type: tanh, static, kinetic, regularization_speed, stribeck_speed}
///           | {type: ambrosio, coefficient, ramp_start_speed, ramp_end_speed}
///   cable_radius, point_mass_radius, points_per_element,
///   targets: [{name, type: plane, point, normal} | {name, type: sphere, center, radius}
///             | {name, type: box, center, half_extents} | {name, type: cylinder, center, axis,
///             radius, half_length} | {name, type: capsule, center, axis, radius, half_length}
///             | {name, type: mesh, file, scale, position, rotation: {axis, angle}}]

#include <filesystem>
#include <string>

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// A normal law map ({type, stiffness, ...} as under `law` above; InputError at its key).
NormalLaw ReadNormalLaw(const YamlValue& value);

/// A friction law map ({type, ...} as under `friction` above).
FrictionLaw ReadFriction(const YamlValue& value);

/// Sets the model's contact; InputError with file, line and key on any mistake. A mesh's relative
/// `file` is taken from `scene_directory`.
void ReadContact(const YamlValue& value, const std::filesystem::path& scene_directory,
                 ModelBuilder* builder);

/// ReadContact on the one YAML document of `yaml_text` (a `contact` section's map; JSON is YAML),
/// for a model built in code (the Python ModelBuilder): `source_name` names it in messages,
/// "SOURCE:LINE:COLUMN: … (key 'KEY')", and a mesh's relative `file` is taken from `directory`.
void ReadContactText(const std::string& yaml_text, const std::string& source_name,
                     const std::filesystem::path& directory, ModelBuilder* builder);

}  // namespace ancfnet
