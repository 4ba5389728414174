#pragma once
/// @file Cross-section and material of an ANCF beam (elements/ancf_beam.hpp), the element
/// parameters made from them, and the reference section frame made from an orientation vector.
/// Invalid input throws InputError.

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/ancf_beam.hpp"

namespace ancfnet {

/// Geometric properties of a beam cross-section in its principal axes (y along d₂, z along d₃),
/// centroid on the beam axis. SI.
struct BeamSection {
  double area = 0.0;                ///< A (m²), > 0
  double second_moment_y = 0.0;     ///< I_y = ∫ z² dA (m⁴), > 0
  double second_moment_z = 0.0;     ///< I_z = ∫ y² dA (m⁴), > 0
  double torsion_constant = 0.0;    ///< Saint-Venant J (m⁴), > 0 (not the polar moment)
  double shear_correction_y = 0.0;  ///< k_y for shear along y, in (0, 1]
  double shear_correction_z = 0.0;  ///< k_z for shear along z, in (0, 1]
};

/// Elastic, isotropic material of a beam.
struct BeamMaterial {
  double youngs_modulus = 0.0;  ///< E (Pa), > 0
  double poisson_ratio = 0.0;   ///< ν, in (−1, 0.5)
  double density = 0.0;         ///< ρ (kg/m³), > 0
  /// Kelvin–Voigt retardation times (s), ≥ 0, as for a cable's material (model/material.hpp):
  /// τ_ε on the axial and shear strains, τ_κ on torsion and bending (elements/ancf_beam.hpp).
  double axial_damping_time = 0.0;
  double bending_damping_time = 0.0;
};

/// Rectangle of height h along y and width b along z: A = bh, I_z = bh³/12, I_y = hb³/12, the
/// Saint-Venant constant J = (a c³/3) [1 − (192/π⁵)(c/a) Σ_{n odd} tanh(nπa/2c)/n⁵] with a ≥ c the
/// longer and shorter sides (Timoshenko & Goodier 1970, §109), and Cowper's (1966) shear
/// correction k = 10(1 + ν)/(12 + 11ν) in both directions. Throws InputError unless h, b > 0
/// and ν ∈ (−1, 0.5).
BeamSection MakeRectangleBeamSection(double height, double width, double poisson_ratio);

/// Solid circle of diameter d: A = πd²/4, I_y = I_z = πd⁴/64, J = πd⁴/32 (the polar moment, exact
/// for a circle), Cowper's (1966) k = 6(1 + ν)/(7 + 6ν). Throws InputError unless d > 0 and
/// ν ∈ (−1, 0.5).
BeamSection MakeCircleBeamSection(double diameter, double poisson_ratio);

/// Element parameters of elements/ancf_beam.hpp with G = E/(2(1 + ν)), the cross-section
/// penalties EA and GA, the rotary inertias ρI_y, ρI_z and the damping times. Throws InputError
/// (the message names the offending quantity) unless L, E, ρ, A, I_y, I_z, J, k_y, k_z > 0,
/// k ≤ 1, ν ∈ (−1, 0.5) and the damping times are ≥ 0.
BeamElementParameters MakeBeamElementParameters(const BeamMaterial& material,
                                                const BeamSection& section, double length);

/// Unit directors (d₂, d₃) of the reference section of a straight beam along `axis`: d₂ is
/// `orientation` with its component along the axis removed, normalised, and d₃ = t × d₂, so that
/// (t, d₂, d₃) is right-handed. Throws InputError if the orientation vector is (within 1e-6 rad)
/// parallel to the axis or either vector is zero.
struct BeamSectionFrame {
  Vector3d d2;
  Vector3d d3;
};
BeamSectionFrame MakeBeamSectionFrame(const Vector3d& axis, const Vector3d& orientation);

}  // namespace ancfnet
