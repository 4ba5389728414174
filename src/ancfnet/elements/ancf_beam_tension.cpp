#include "ancfnet/elements/ancf_beam_tension.hpp"

#include "ancfnet/common/quadrature.hpp"

namespace ancfnet {

Vector3d CalcBeamSectionNormal(const Vector24d& e, double xi) {
  // d₂ from blocks 2 (node A) and 6 (node B), d₃ from blocks 3 and 7.
  const Vector3d d2 = (1.0 - xi) * e.segment<3>(6) + xi * e.segment<3>(18);
  const Vector3d d3 = (1.0 - xi) * e.segment<3>(9) + xi * e.segment<3>(21);
  return d2.cross(d3).normalized();
}

double CalcBeamGaussPointAxialForce(const BeamElementParameters& p, const Vector24d& e, double xi) {
  const GaussRule& rule = GetGaussRule(kBeamAxialGaussPoints);
  double force = 0.0;
  for (int i = 0; i < rule.size; ++i)
    force += CalcGaussPointBasis(rule, i, xi) * p.axial_stiffness *
             CalcBeamAxialStrain(p, e, rule.points[i]);
  return force;
}

Vector3d CalcBeamMidpointForce(const BeamElementParameters& p, const Vector24d& e) {
  Vector24d force;
  CalcBeamInternalForce(p, e, Vector24d::Zero(), {.force = &force});
  return force.segment<3>(12);  // block 4: r_B
}

double CalcBeamStationTension(const Vector24d& e, const CableStationForces& forces, double xi) {
  return InterpolateStationForce(forces, xi).dot(CalcBeamSectionNormal(e, xi));
}

}  // namespace ancfnet
