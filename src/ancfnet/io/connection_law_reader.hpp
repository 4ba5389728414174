#pragma once
/// @file Reads a connection law (elements/connection_law.hpp) from a scene file:
///   {type: linear, stiffness: k}                     T_s = k e
///   {type: tension_only, stiffness: k, gap: g}       T_s = k (e − g) for e > g, else 0
///   {type: polynomial, k1: k1, k3: k3}               T_s = k1 e + k3 e³
///   {type: table, table: [[e, T], ...]}              measured, linear between rows
/// each with an optional `damping: b` (N s/m, constant) or `damping_time: β` (s, b = β dT_s/de).

#include "ancfnet/elements/connection_law.hpp"
#include "ancfnet/io/yaml_reader.hpp"

namespace ancfnet {

/// The law described by `value`; InputError with file, line and key on any mistake.
ConnectionLaw ReadConnectionLaw(const YamlValue& value);

}  // namespace ancfnet
