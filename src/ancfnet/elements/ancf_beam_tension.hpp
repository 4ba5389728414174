#pragma once
/// @file Tension of the ANCF beam element for outputs and failure checks: its section's normal
/// force N = EA Γ₁ (Simo 1985; docs/theory.md, "Tension of a beam"), recovered as the cable's
/// tension is (elements/ancf_cable_tension.hpp) but from the beam's own forces: the resultant
/// force the element passes from node to node, projected on the section's normal.

#include "ancfnet/elements/ancf_beam.hpp"
#include "ancfnet/elements/ancf_cable_tension.hpp"

namespace ancfnet {

/// Unit normal of the section at ξ ∈ [0, 1], n = d₂ × d₃ / |d₂ × d₃| with the interpolated
/// directors d = (1 − ξ) d_A + ξ d_B.
Vector3d CalcBeamSectionNormal(const Vector24d& e, double xi);

/// Normal force N(ξ) (N) of the polynomial of degree 2 through N_i = EA Γ₁(ξ_i) at the element's
/// kBeamAxialGaussPoints axial Gauss points ξ_i (CalcGaussPointBasis), where Γ₁ enters the
/// element's equations. Accurate in a beam of one element whose end sections are free (its
/// Gauss-point forces are then fixed by equilibrium alone); elsewhere use CalcBeamStationTension.
double CalcBeamGaussPointAxialForce(const BeamElementParameters& p, const Vector24d& e, double xi);

/// Elastic resultant force at the element's midpoint, F_M = Q_{r_B} = −Q_{r_A} (N): the elastic
/// internal force on the position of its end node (CalcBeamInternalForce with ė = 0; the two are
/// opposite because U depends on r only through r′). As for the cable
/// (CalcCableMidpointForce), it is exactly the section force at ξ = ½ in a static equilibrium
/// under a load uniform along the element. Kelvin–Voigt damping excluded.
Vector3d CalcBeamMidpointForce(const BeamElementParameters& p, const Vector24d& e);

/// Recovered tension (N) at ξ ∈ [0, 1]: N(ξ) = F(ξ) · n(ξ), the section force F interpolated
/// linearly between the stations on each half of the element and projected on the section's
/// normal n (CalcBeamSectionNormal), not on the axis' tangent, which a shear strain turns away
/// from n. A beam is elastic in compression too: N < 0 is returned as is.
double CalcBeamStationTension(const Vector24d& e, const CableStationForces& forces, double xi);

}  // namespace ancfnet
