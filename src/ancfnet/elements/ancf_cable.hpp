#pragma once
/// @file The 3D gradient-deficient ANCF cable element (Gerstmayr & Shabana 2006; Berzeri &
/// Shabana 2000): two nodes with coordinates e = [r_A, r_A', r_B, r_B'], cubic Hermite
/// interpolation, Green axial strain and the exact curvature. Pure functions on fixed-size types;
/// the derivation is in docs/theory.md, section "ANCF cable element".

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// How bending is measured.
enum class BendingModel {
  /// The exact curvature κ = |r' × r''|/|r'|³ (Gerstmayr & Shabana 2006): objective and exact at
  /// any stretch, singular where |r'| → 0.
  kExactCurvature,
  /// U_b = ½ EI ∫ |r''|² dx (Berzeri & Shabana 2000, the "simple model"): linear and constant
  /// stiffness, exact for small stretch, regular at any |r'| — for ropes and net threads, whose
  /// slack parts can shrink |r'| without limit.
  kSecondDerivative,
};

/// Constant properties of one cable element. All SI.
struct CableElementParameters {
  double length = 0.0;             ///< reference (stress-free) length L (m), > 0
  double axial_stiffness = 0.0;    ///< EA (N), > 0
  double bending_stiffness = 0.0;  ///< EI (N m²), ≥ 0
  double mass_per_length = 0.0;    ///< ρA (kg/m), > 0
  /// Kelvin–Voigt retardation times (s), ≥ 0: N = EA (ε + τ_ε ε̇), M = EI (κ + τ_κ κ̇) (the rate
  /// of the curvature's magnitude, so rigid rotation dissipates nothing).
  double axial_damping_time = 0.0;
  double bending_damping_time = 0.0;
  /// Rope law: N = EA max(ε + τ_ε ε̇, 0) while stretched, 0 while slack. Bending still acts.
  bool tension_only = false;
  /// ε_s ≥ 0: with tension_only, the smooth rope law N = EA φ(ε) (plus damping EA τ φ′ ε̇) of
  /// elements/rope_law.hpp: exact for |ε| ≥ ε_s, zero below −ε_s, a quadratic between (EA ε_s/4
  /// at ε = 0), no kink, so Newton converges where threads go slack and taut. 0: the exact max.
  double rope_smoothing_strain = 0.0;
  BendingModel bending_model = BendingModel::kExactCurvature;
  /// Gauss points along the element for the axial and the bending terms (docs/theory.md says why
  /// these defaults avoid membrane locking).
  int axial_gauss_points = 3;
  int bending_gauss_points = 4;
};

/// Which outputs CalcCableInternalForce fills; null pointers are skipped.
struct CableForceOutputs {
  Vector12d* force = nullptr;  ///< Q = ∂U/∂e + Q_visc (N), the internal generalised force
  Vector12d* viscous_force = nullptr;  ///< the Kelvin–Voigt part Q_visc alone (N)
  Matrix12d* stiffness = nullptr;      ///< ∂Q/∂e (N/m)
  Matrix12d* damping = nullptr;        ///< ∂Q/∂ė (N s/m)
};

/// Internal generalised force of the element and, when asked, its exact Jacobians:
///   Q = ∫₀ᴸ [ N ∂ε/∂e + EI (κ + τ_κ κ̇) ∂κ/∂e ] dx,  N = EA (ε + τ_ε ε̇),
/// with ε = (r'·r' − 1)/2 (Gerstmayr & Shabana 2006, eq. 9) and the curvature vector
/// k = (r' × r'') / |r'|³, |k| = κ (eq. 11). Outputs are overwritten, not accumulated.
void CalcCableInternalForce(const CableElementParameters& p, const Vector12d& e,
                            const Vector12d& e_dot, const CableForceOutputs& out);

/// Strain energy U = ½ ∫₀ᴸ (EA ε² + EI κ²) dx (J), with ε replaced by max(ε, 0) for ropes.
double CalcCableStrainEnergy(const CableElementParameters& p, const Vector12d& e);

/// Consistent mass matrix M = ∫₀ᴸ ρA Sᵀ S dx (kg), constant; integrated exactly.
Matrix12d CalcCableMassMatrix(const CableElementParameters& p);

/// Generalised force of a load per unit length w (N/m), constant along the element:
/// Q = ∫₀ᴸ Sᵀ w dx = [L/2 w, L²/12 w, L/2 w, −L²/12 w].
Vector12d CalcCableDistributedForce(const CableElementParameters& p, const Vector3d& w);

/// Axial Green strain ε and curvature κ at ξ ∈ [0, 1] (for outputs and tests).
struct CableStrain {
  double axial = 0.0;
  double curvature = 0.0;
};
CableStrain CalcCableStrain(const CableElementParameters& p, const Vector12d& e, double xi);

/// Elastic axial energy per unit reference length (J/m) at an axial strain ε, ∫ N dε: EA ε²/2;
/// for ropes EA max(ε, 0)²/2, or EA ψ(ε) with the smooth rope law.
double CalcCableAxialEnergyDensity(const CableElementParameters& p, double strain);

/// Elastic axial force (N) for an axial strain ε: EA ε; for ropes EA max(ε, 0), or with the
/// smooth rope law EA φ(ε) of elements/rope_law.hpp (docs/theory.md, "Smooth rope law").
double CalcCableAxialForce(const CableElementParameters& p, double strain);

}  // namespace ancfnet
