#pragma once
/// @file Materials and cross-sections, and the cable properties derived from them.

#include <string>

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/ancf_cable.hpp"

namespace ancfnet {

/// Linear elastic material with optional Kelvin–Voigt damping. SI units.
struct Material {
  double youngs_modulus = 0.0;  ///< E (Pa), > 0
  double density = 0.0;         ///< ρ (kg/m³), > 0
  /// Kelvin–Voigt retardation times (s), ≥ 0: σ = E (ε + τ ε̇), separately for the axial strain
  /// and the curvature.
  double axial_damping_time = 0.0;
  double bending_damping_time = 0.0;
};

/// Cross-section of a cable. The cable element bends isotropically, so one second moment I is
/// kept (for a rectangle, about the axis parallel to its width: I = w h³ / 12).
struct Section {
  double area = 0.0;           ///< A (m²), > 0
  double second_moment = 0.0;  ///< I (m⁴), ≥ 0
  double radius = 0.0;         ///< outer radius used for drawing (and later contact) (m)
};

/// Solid circle of diameter d > 0 (m): A = π d²/4, I = π d⁴/64.
Section MakeCircleSection(double diameter);
/// Solid rectangle of width w > 0 and height h > 0 (m): A = w h, I = w h³/12.
Section MakeRectangleSection(double width, double height);

/// Properties of one cable, uniform along it.
struct CableProperties {
  double axial_stiffness = 0.0;       ///< EA (N)
  double bending_stiffness = 0.0;     ///< EI (N m²)
  double mass_per_length = 0.0;       ///< ρA (kg/m)
  double axial_damping_time = 0.0;    ///< τ_ε (s)
  double bending_damping_time = 0.0;  ///< τ_κ (s)
  double radius = 0.0;                ///< for drawing (m)
  bool tension_only = false;          ///< rope law N = EA max(ε, 0)
  double rope_smoothing_strain = 0.0;  ///< ε_s of the smooth rope law (elements/ancf_cable.hpp)
  BendingModel bending_model = BendingModel::kExactCurvature;  ///< elements/ancf_cable.hpp
  int axial_gauss_points = 3;         ///< see docs/theory.md, "Quadrature and locking"
  int bending_gauss_points = 4;
};

/// Cable properties of a material and a section: EA, EI, ρA and the damping times.
CableProperties MakeCableProperties(const Material& material, const Section& section);

/// The smoothing strain ε_s of ropes by default: on a slack pendulum its trajectory error is that
/// of a step of 10⁻³ s, and it takes 80 % of the step cuts of ε_s = 10⁻⁵ (docs/theory.md, "Smooth
/// rope law and simple bending").
inline constexpr double kDefaultRopeSmoothingStrain = 1e-4;

/// Properties of a rope (a net thread, a tether, a tension-only cable) of this material and
/// section: the rope law (tension only), smoothed over kDefaultRopeSmoothingStrain (an error of
/// at most EA ε_s/2 in the axial force; it removes the Newton failures of ropes going slack and
/// taut), and the simple bending model ½ EI ∫|r''|², regular where a slack rope's |r'| shrinks
/// (the exact curvature |r′ × r″|/|r′|³ blows up there and Newton fails).
CableProperties MakeRopeProperties(const Material& material, const Section& section);

}  // namespace ancfnet
