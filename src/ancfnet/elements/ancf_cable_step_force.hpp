#pragma once
/// @file The cable's elastic force over a whole time step, for the midpoint rule: a discrete
/// gradient of the strain energy, so that its work over the step equals U(e₁) − U(e₀) exactly
/// (docs/theory.md, "Energy-consistent midpoint rule").

#include <array>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/ancf_cable.hpp"

namespace ancfnet {

/// What the correction needs of the step's start e₀, the same at every Newton iteration of a
/// step: computed once per step (CalcCableStepStart), not at every residual.
struct CableStepStart {
  Vector12d e = Vector12d::Zero();                     ///< e₀
  double energy = 0.0;                                 ///< U(e₀) (J)
  std::array<double, kMaxGaussPoints> axial_strain{};  ///< ε₀ at the axial Gauss points
  std::array<double, kMaxGaussPoints> axial_energy{};  ///< W(ε₀) there (J/m)
};

/// The step-start quantities of CalcCableStepForceCorrection at e₀.
CableStepStart CalcCableStepStart(const CableElementParameters& p, const Vector12d& e0);

/// ΔQ such that Q̄ = Q_el(e_m) + ΔQ, e_m = (e₀ + e₁)/2, does the work (e₁ − e₀)·Q̄ = U(e₁) − U(e₀)
/// exactly, Q_el(e_m) the element's elastic force at the midpoint (its force less the
/// Kelvin–Voigt part, CableForceOutputs). Axial: at each Gauss point the axial force at the
/// midpoint strain becomes the divided difference N̄ = (W(ε₁) − W(ε₀))/(ε₁ − ε₀) of the energy
/// density W (CalcCableAxialEnergyDensity); since ε is quadratic in e, ε₁ − ε₀ = (∂ε/∂e)(e_m)·Δe
/// and the axial work is exact and the force stays objective, so momentum is kept (Simo & Tarnow
/// 1992, eq. 25). Bending, whose exact curvature is not polynomial in e: what remains of the
/// energy error, r, is added along Δe, ΔQ_b = r W Δe/(Δeᵀ W Δe) with W = diag(1, L²) on positions
/// and slopes (Gonzalez 1996, eq. 12). Zero where e₁ = e₀. With `jacobian`, also ∂ΔQ/∂e_m
/// (e₁ = 2 e_m − e₀ moving with it) of the axial part, for the Newton iteration matrix.
Vector12d CalcCableStepForceCorrection(const CableElementParameters& p, const CableStepStart& start,
                                       const Vector12d& e1, const Vector12d& elastic_force,
                                       Matrix12d* jacobian = nullptr);

/// The same from e₀ itself (CalcCableStepStart at every call).
inline Vector12d CalcCableStepForceCorrection(const CableElementParameters& p, const Vector12d& e0,
                                              const Vector12d& e1, const Vector12d& elastic_force,
                                              Matrix12d* jacobian = nullptr) {
  return CalcCableStepForceCorrection(p, CalcCableStepStart(p, e0), e1, elastic_force, jacobian);
}

}  // namespace ancfnet
