#pragma once
/// @file Tension of the ANCF cable element for outputs and failure checks, recovered from the
/// quantities the element's equations determine: the axial force at its axial Gauss points and its
/// resultant end force. The axial strain at an arbitrary point is no such quantity: in a stiff
/// element it is EA times a tiny interpolation error (docs/theory.md, "Tension recovery").

#include "ancfnet/elements/ancf_cable.hpp"

namespace ancfnet {

/// Tension T = N(ε) λ (N) for an axial Green strain ε: the magnitude of the elastic section force
/// N r', with N of the element's axial law (CalcCableAxialForce) and the stretch
/// λ = |r'| = √(1 + 2ε). N is conjugate to ε (a force per unit reference length of r'); N λ is
/// the force a cut through the stretched cable carries. ε > −½.
double CalcCableTension(const CableElementParameters& p, double strain);

/// Tension (N) at ξ ∈ [0, 1] of the polynomial of degree n − 1 through the tensions T_i at the
/// element's n axial Gauss points ξ_i (Lagrange interpolation, extrapolation outside them):
///   T(ξ) = Σ_i T_i ∏_{j≠i} (ξ − ξ_j) / (ξ_i − ξ_j),  T_i = CalcCableTension(p, ε(ξ_i)),
/// the Gauss-point extrapolation of Hinton & Campbell (1974). The Gauss points are where the axial
/// force enters the element's equations; their forces are fixed by equilibrium alone (statically
/// determinate) in a cable of one element whose end slopes are free, and there this is accurate.
/// In a cable of several elements they are not (docs/theory.md, "Tension recovery"): use
/// CalcCableStationTension. No lower bound for ropes: the caller clamps.
double CalcCableGaussPointTension(const CableElementParameters& p, const Vector12d& e, double xi);

/// Elastic section force at the element's midpoint, F_M (N): the elastic internal force on the
/// position of its end node, F_M = Q_{r_B} = −Q_{r_A} (CalcCableInternalForce with ė = 0; the two
/// are opposite because S₁ + S₃ = 1). It is the force the element passes from node to node; in a
/// static equilibrium under a load uniform along the element (gravity, a distributed load) it is
/// exactly the section force at ξ = ½, however stiff the element. Kelvin–Voigt damping excluded.
Vector3d CalcCableMidpointForce(const CableElementParameters& p, const Vector12d& e);

/// Section forces (N) at an element's three stations (analysis/cable_tension.hpp fills them).
struct CableStationForces {
  Vector3d start = Vector3d::Zero();   ///< at ξ = 0
  Vector3d middle = Vector3d::Zero();  ///< at ξ = ½
  Vector3d end = Vector3d::Zero();     ///< at ξ = 1
};

/// The section force F(ξ) (N) at ξ ∈ [0, 1], interpolated linearly between the stations on each
/// half of the element.
Vector3d InterpolateStationForce(const CableStationForces& forces, double xi);

/// Recovered tension (N) at ξ ∈ [0, 1]: T(ξ) = F(ξ) · r'(ξ)/|r'(ξ)|, the section force F
/// (InterpolateStationForce) projected on the tangent; max(T, 0) for a tension-only cable.
double CalcCableStationTension(const CableElementParameters& p, const Vector12d& e,
                               const CableStationForces& forces, double xi);

}  // namespace ancfnet
