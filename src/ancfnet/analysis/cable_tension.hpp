#pragma once
/// @file The tension along a cable, recovered element by element from the elements' resultant
/// forces (docs/theory.md, "Tension recovery"): for the VTK `tension` field, the net probe
/// `max_tension` and the breaking of threads.

#include "ancfnet/elements/ancf_cable_tension.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// Section forces (N) at the stations ξ = 0, ½, 1 of element k (0 ≤ k < cable.num_elements) of
/// `cable` at coordinates q. The middle one is the element's midpoint force F_M
/// (CalcCableMidpointForce; CalcBeamMidpointForce, the beam's own, for a beam element); a node
/// between two elements gets the section force interpolated linearly in arc length between their
/// midpoints, F = (L_k F_{M,k−1} + L_{k−1} F_{M,k}) / (L_{k−1} + L_k); an end node of a cable of
/// several elements the linear extrapolation from the two nearest midpoints. Exact, with
/// CalcCableStationTension, in a static equilibrium under loads uniform along the cable. A cable of
/// one element has no second midpoint: its end nodes get the Gauss-point tension along the tangent,
/// CalcCableGaussPointTension(ξ) r'/|r'| (a beam: CalcBeamGaussPointAxialForce(ξ) along the
/// section's normal). Concentrated forces at interior nodes (a link, a point load) are spread over
/// the half elements either side. Elastic forces only; up to three element force evaluations.
CableStationForces CalcCableStationForces(const Model& model, const Cable& cable, Index k,
                                          const VectorXd& q);

/// Largest recovered tension along `cable` (N): the largest CalcCableElementTension at the
/// stations of its elements.
double CalcCableMaxTension(const Model& model, const Cable& cable, const VectorXd& q);

/// Recovered tension (N) at ξ ∈ [0, 1] of element k of `cable` with the section forces `forces`
/// of CalcCableStationForces: CalcCableStationTension for a cable element, the section's normal
/// force CalcBeamStationTension for a beam element.
double CalcCableElementTension(const Model& model, const Cable& cable, Index k, const VectorXd& q,
                               const CableStationForces& forces, double xi);

}  // namespace ancfnet
