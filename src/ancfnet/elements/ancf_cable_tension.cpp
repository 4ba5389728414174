#include "ancfnet/elements/ancf_cable_tension.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {

double CalcCableTension(const CableElementParameters& p, double strain) {
  return CalcCableAxialForce(p, strain) * std::sqrt(1.0 + 2.0 * strain);
}

double CalcCableGaussPointTension(const CableElementParameters& p, const Vector12d& e, double xi) {
  const GaussRule& rule = GetGaussRule(p.axial_gauss_points);
  double tension = 0.0;
  for (int i = 0; i < rule.size; ++i)
    tension += CalcGaussPointBasis(rule, i, xi) *
               CalcCableTension(p, CalcCableStrain(p, e, rule.points[i]).axial);
  return tension;
}

Vector3d CalcCableMidpointForce(const CableElementParameters& p, const Vector12d& e) {
  Vector12d force;
  CalcCableInternalForce(p, e, Vector12d::Zero(), {.force = &force});
  return force.segment<3>(6);
}

Vector3d InterpolateStationForce(const CableStationForces& forces, double xi) {
  return xi <= 0.5 ? forces.start + (2.0 * xi) * (forces.middle - forces.start)
                   : forces.middle + (2.0 * xi - 1.0) * (forces.end - forces.middle);
}

double CalcCableStationTension(const CableElementParameters& p, const Vector12d& e,
                               const CableStationForces& forces, double xi) {
  const Vector3d force = InterpolateStationForce(forces, xi);
  const HermiteShape shape = CalcHermiteShape(xi, p.length);
  const Vector3d slope = Eigen::Map<const Eigen::Matrix<double, 3, 4>>(e.data()) * shape.ds;
  const double tension = force.dot(slope) / slope.norm();
  return p.tension_only ? std::max(tension, 0.0) : tension;
}

}  // namespace ancfnet
