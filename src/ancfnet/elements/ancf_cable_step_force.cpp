#include "ancfnet/elements/ancf_cable_step_force.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {

Vector12d CalcCableStepForceCorrection(const CableElementParameters& p, const Vector12d& e0,
                                       const Vector12d& e1, const Vector12d& elastic_force) {
  Vector12d correction = Vector12d::Zero();
  const Vector12d de = e1 - e0;
  if (de.isZero(0.0)) return correction;
  const Vector12d em = 0.5 * (e0 + e1);
  using Matrix34d = Eigen::Matrix<double, 3, 4>;
  const GaussRule& axial = GetGaussRule(p.axial_gauss_points);
  for (int i = 0; i < axial.size; ++i) {
    const HermiteShape shape = CalcHermiteShape(axial.points[i], p.length);
    const Vector3d a0 = Eigen::Map<const Matrix34d>(e0.data()) * shape.ds;
    const Vector3d a1 = Eigen::Map<const Matrix34d>(e1.data()) * shape.ds;
    const Vector3d am = Eigen::Map<const Matrix34d>(em.data()) * shape.ds;
    const double eps0 = 0.5 * (a0.squaredNorm() - 1.0);
    const double eps1 = 0.5 * (a1.squaredNorm() - 1.0);
    const double eps_m = 0.5 * (am.squaredNorm() - 1.0);
    // N̄ as a divided difference while it is well above round-off, else the force at the mean
    // strain (equal to second order in ε₁ − ε₀).
    const double change = eps1 - eps0;
    const double mean_force =
        std::abs(change) > 1e-7 * std::max(std::abs(eps0) + std::abs(eps1), 1e-9)
            ? (CalcCableAxialEnergyDensity(p, eps1) - CalcCableAxialEnergyDensity(p, eps0)) /
                  change
            : CalcCableAxialForce(p, 0.5 * (eps0 + eps1));
    const double excess = mean_force - CalcCableAxialForce(p, eps_m);
    correction += (axial.weights[i] * p.length * excess) * DistributeForce(shape.ds, am);
  }
  // The bending energy's share of the error (and round-off of the axial part), along Δe.
  const double u0 = CalcCableStrainEnergy(p, e0);
  const double u1 = CalcCableStrainEnergy(p, e1);
  const double residual = u1 - u0 - de.dot(elastic_force + correction);
  // At round-off level of U the residual is noise, which a tiny Δe would turn into a force.
  if (!(std::abs(residual) > 1e-13 * (std::abs(u0) + std::abs(u1)))) return correction;
  Vector12d weighted = de;
  for (int node = 0; node < 2; ++node)
    weighted.segment<3>(6 * node + 3) *= p.length * p.length;
  correction += (residual / de.dot(weighted)) * weighted;
  return correction;
}

}  // namespace ancfnet
