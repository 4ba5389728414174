#include "ancfnet/analysis/cable_tension.hpp"

#include <algorithm>
#include <limits>

#include "ancfnet/elements/ancf_beam_tension.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {
namespace {

// Element k of the cable: its centre line's parameters and coordinates, and, for a beam
// element, the beam's.
struct ElementAt {
  const CableElementParameters& p;
  Vector12d e;
  const BeamElement* beam = nullptr;
  Vector24d beam_e = Vector24d::Zero();
};

ElementAt GetElement(const Model& model, const Cable& cable, Index k, const VectorXd& q) {
  const CableElement& element = model.elements()[cable.first_element + k];
  ElementAt el{element.parameters, model.Gather(element, q)};
  if (element.beam >= 0) {
    el.beam = &model.beam_elements()[element.beam];
    el.beam_e = model.Gather(*el.beam, q);
  }
  return el;
}

// The elastic section force at the element's midpoint: the beam's own for a beam element.
Vector3d MidpointForce(const ElementAt& el) {
  return el.beam ? CalcBeamMidpointForce(el.beam->parameters, el.beam_e)
                 : CalcCableMidpointForce(el.p, el.e);
}

// The section force at node ξ ∈ {0, 1} of a lone element: its Gauss-point tension along r', or
// a beam's Gauss-point normal force along its section's normal.
Vector3d LoneElementEndForce(const ElementAt& el, double xi) {
  if (el.beam)
    return CalcBeamGaussPointAxialForce(el.beam->parameters, el.beam_e, xi) *
           CalcBeamSectionNormal(el.beam_e, xi);
  const Vector3d slope = Eigen::Map<const Eigen::Matrix<double, 3, 4>>(el.e.data()) *
                         CalcHermiteShape(xi, el.p.length).ds;
  return CalcCableGaussPointTension(el.p, el.e, xi) * slope.normalized();
}

double StationTension(const ElementAt& el, const CableStationForces& forces, double xi) {
  return el.beam ? CalcBeamStationTension(el.beam_e, forces, xi)
                 : CalcCableStationTension(el.p, el.e, forces, xi);
}

// Section force at arc length `s` from the midpoint of the element of length `length_a` and
// midpoint force `force_a`, along the line to the next midpoint (element of length `length_b`).
Vector3d AlongMidpoints(const Vector3d& force_a, double length_a, const Vector3d& force_b,
                        double length_b, double s) {
  return force_a + (2.0 * s / (length_a + length_b)) * (force_b - force_a);
}

}  // namespace

CableStationForces CalcCableStationForces(const Model& model, const Cable& cable, Index k,
                                          const VectorXd& q) {
  const ElementAt el = GetElement(model, cable, k, q);
  CableStationForces forces;
  forces.middle = MidpointForce(el);
  const double half = 0.5 * el.p.length;
  if (cable.num_elements == 1) {
    forces.start = LoneElementEndForce(el, 0.0);
    forces.end = LoneElementEndForce(el, 1.0);
    return forces;
  }
  if (k > 0) {
    const ElementAt before = GetElement(model, cable, k - 1, q);
    const double length = before.p.length;
    const Vector3d force = MidpointForce(before);
    forces.start = AlongMidpoints(force, length, forces.middle, el.p.length, 0.5 * length);
    if (k + 1 == cable.num_elements)  // the last element: extrapolate to the cable's end
      forces.end =
          AlongMidpoints(force, length, forces.middle, el.p.length, 0.5 * length + el.p.length);
  }
  if (k + 1 < cable.num_elements) {
    const ElementAt after = GetElement(model, cable, k + 1, q);
    const Vector3d force = MidpointForce(after);
    forces.end = AlongMidpoints(forces.middle, el.p.length, force, after.p.length, half);
    if (k == 0)  // the first element: extrapolate to the cable's start
      forces.start = AlongMidpoints(forces.middle, el.p.length, force, after.p.length, -half);
  }
  return forces;
}

double CalcCableMaxTension(const Model& model, const Cable& cable, const VectorXd& q) {
  double tension = -std::numeric_limits<double>::infinity();
  for (Index k = 0; k < cable.num_elements; ++k) {
    const ElementAt el = GetElement(model, cable, k, q);
    const CableStationForces forces = CalcCableStationForces(model, cable, k, q);
    for (double xi : {0.0, 0.5, 1.0}) tension = std::max(tension, StationTension(el, forces, xi));
  }
  return tension;
}

double CalcCableElementTension(const Model& model, const Cable& cable, Index k, const VectorXd& q,
                               const CableStationForces& forces, double xi) {
  return StationTension(GetElement(model, cable, k, q), forces, xi);
}

}  // namespace ancfnet
