#pragma once
/// @file Reads what makes a cable of a scene a beam of ANCF beam elements (docs/scene-format.md,
/// "Beams"): on the cable `element: ancf_beam` and `orientation: [x, y, z]` (the direction of d₂);
/// on its material `poisson_ratio: ν` or `shear_modulus: G`; its section's second moments and
/// torsion constant (from `shape: circle | rectangle`, or given with `shape: general`); the same
/// `element: ancf_beam` on a net makes its threads beams (io/net_reader.hpp).

#include <optional>

#include "ancfnet/io/scene_library.hpp"
#include "ancfnet/io/yaml_reader.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

/// ν of a material map: `poisson_ratio`, or E/(2G) − 1 from `shear_modulus` G; empty when it has
/// neither. Fails at the key when ν is outside (−1, 0.5) or both keys are given.
std::optional<double> ReadPoissonRatio(const YamlMap& material);

/// Whether `element` of a cable or net map is `ancf_beam` (else `cable`, the default).
bool ReadIsBeam(const YamlMap& map);

/// The beam material and section named by the `material` and `section` keys of a cable or net
/// map, with the material's damping times; the orientation is left zero. Fails at the key at
/// fault: a material without ν, a section without the inertias a beam needs.
BeamCableSpec ReadBeamMaterialAndSection(const YamlMap& map, const Library& library);

/// The beam of a cable map whose `element` is `ancf_beam`, or empty for `element: cable` (the
/// default). `axis` is end − start. Fails at the key at fault: an orientation of zero length or
/// parallel to the axis, a material without ν, a section without the inertias a beam needs.
std::optional<BeamCableSpec> ReadBeamCable(const YamlMap& cable, const Vector3d& axis,
                                           const Library& library);

}  // namespace ancfnet
