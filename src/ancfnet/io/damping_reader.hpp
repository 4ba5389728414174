#pragma once
/// @file Reads the `damping` map of a scene (model/damping_spec.hpp):
///   rayleigh: {alpha: α, beta: β}  or  {fit: [[f₁, ζ₁], [f₂, ζ₂]]}   (Hz, ratios)
///   modal: {modes: k, ratios: [ζ₁, …, ζ_k]}  or  {modes: k, table: [[f, ζ], …]}

#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// Sets the model's Rayleigh and modal damping; InputError with file, line and key on any mistake.
void ReadDamping(const YamlValue& value, ModelBuilder* builder);

}  // namespace ancfnet
