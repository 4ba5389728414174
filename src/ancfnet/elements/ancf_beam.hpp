#pragma once
/// @file The 3D shear-deformable, torsional ANCF beam element: two nodes with the position and
/// the three gradients r_x, r_y, r_z (24 coordinates, elements/beam_shape.hpp; Shabana & Yakoub
/// 2001), with the structural mechanics strain energy of a Simo–Reissner rod (Nachbagauer,
/// Pechstein, Irschik & Gerstmayr 2011; Nachbagauer, Gruber & Gerstmayr 2013) and an assumed
/// shear strain against shear locking. Pure functions on fixed-size types; the derivation is in
/// docs/theory.md, section "ANCF beam element".

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/beam_shape.hpp"

namespace ancfnet {

/// Gauss points of the axial strain Γ₁ (Γ₁ of a cubic axis is quadratic in ξ: three points leave
/// no zero-energy mode).
inline constexpr int kBeamAxialGaussPoints = 3;

/// Constant properties of one beam element in its section frame (d₂, d₃). All SI.
struct BeamElementParameters {
  double length = 0.0;               ///< reference (stress-free) length L (m), > 0
  double axial_stiffness = 0.0;      ///< EA (N), > 0
  double shear_stiffness_y = 0.0;    ///< k_y G A, shear along d₂ (N), > 0
  double shear_stiffness_z = 0.0;    ///< k_z G A, shear along d₃ (N), > 0
  double torsional_stiffness = 0.0;  ///< G J (N m²), > 0
  double bending_stiffness_y = 0.0;  ///< E I_y, I_y = ∫ z² dA, bending about d₂ (N m²), > 0
  double bending_stiffness_z = 0.0;  ///< E I_z, I_z = ∫ y² dA, bending about d₃ (N m²), > 0
  /// Penalties on the deformation of the cross-section, which the rod theory does not have:
  /// ½ (|d₂|² − 1) and ½ (|d₃|² − 1) with `section_normal_stiffness` (EA by default), d₂·d₃ with
  /// `section_shear_stiffness` (GA by default) (N).
  double section_normal_stiffness = 0.0;
  double section_shear_stiffness = 0.0;
  double mass_per_length = 0.0;   ///< ρA (kg/m), > 0
  double rotary_inertia_y = 0.0;  ///< ρ I_y = ∫ ρ z² dA (kg m), weighs |ḋ₃|², ≥ 0
  double rotary_inertia_z = 0.0;  ///< ρ I_z = ∫ ρ y² dA (kg m), weighs |ḋ₂|², ≥ 0
  /// Kelvin–Voigt retardation times (s), ≥ 0, as for the cable (elements/ancf_cable.hpp): the
  /// force strains Γ₁, Γ₂, Γ₃ carry EA (Γ₁ + τ_ε Γ̇₁), kGA (Γ + τ_ε Γ̇), the moment strains K₁,
  /// K₂, K₃ (and the shear remainders in K̃) GJ (K₁ + τ_κ K̇₁), EI (K̃ + τ_κ K̃̇). The
  /// cross-section penalties are undamped. A mode of strain s alone has ζ = τ ω / 2.
  double axial_damping_time = 0.0;
  double bending_damping_time = 0.0;
};

/// Which outputs CalcBeamInternalForce fills; null pointers are skipped.
struct BeamForceOutputs {
  Vector24d* force = nullptr;  ///< Q = ∂U/∂e + Q_visc (N), the internal generalised force
  Vector24d* viscous_force = nullptr;  ///< the Kelvin–Voigt part Q_visc alone (N)
  Matrix24d* stiffness = nullptr;  ///< ∂Q/∂e; = ∂²U/∂e², symmetric, when undamped or at rest
  Matrix24d* damping = nullptr;  ///< ∂Q/∂ė = Σ τᵢ kᵢ ∇sᵢ ∇sᵢᵀ, constant in ė (N s/m)
};

/// Internal generalised force Q = ∂U/∂e + Q_visc of the element and, when asked, its exact
/// Jacobians, with
///   U = ½ ∫₀ᴸ [EA Γ₁² + k_yGA Γ₂² + k_zGA Γ₃² + GJ K₁² + EI_y K̃₂² + EI_z K̃₃²
///              + cross-section penalties] dx,
/// the Reissner strains Γ = Rᵀ r' − e₁, K = axial(Rᵀ R') written with the normalised directors
/// (docs/theory.md, eq. B4–B9), Γ₂, Γ₃ sampled at the two Gauss points and their remainder moved
/// into the curvatures K̃ (eq. B10), and the Kelvin–Voigt force Q_visc = Σ τᵢ kᵢ ṡᵢ ∇sᵢ,
/// ṡᵢ = ∇sᵢ·ė, over the same strains (eq. B14). Outputs are overwritten, not accumulated.
void CalcBeamInternalForce(const BeamElementParameters& p, const Vector24d& e,
                           const Vector24d& e_dot, const BeamForceOutputs& out);

/// Axial strain Γ₁ = r'·(d₂ × d₃) / (|d₂| |d₃|) − 1 at ξ ∈ [0, 1] (eq. B4): the stretch of the
/// axis along the section's normal, to which the section's normal force N = EA Γ₁ is conjugate.
double CalcBeamAxialStrain(const BeamElementParameters& p, const Vector24d& e, double xi);

/// Strain energy U (J) of the same integrals.
double CalcBeamStrainEnergy(const BeamElementParameters& p, const Vector24d& e);

/// Consistent mass matrix M = ∫₀ᴸ [ρA Sᵣᵀ Sᵣ + ρI_z S₂ᵀ S₂ + ρI_y S₃ᵀ S₃] dx (kg, kg m²), with
/// r = Sᵣ e, d₂ = S₂ e, d₃ = S₃ e: the kinetic energy ½ ∫∫ ρ |ṙ(x, y, z)|² dA dx of a section with
/// its centroid on the axis and principal axes d₂, d₃. Constant; integrated exactly.
Matrix24d CalcBeamMassMatrix(const BeamElementParameters& p);

}  // namespace ancfnet
