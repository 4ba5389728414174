#include "ancfnet/elements/ancf_cable_step_force.hpp"

#include <algorithm>
#include <cmath>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/elements/rope_law.hpp"

namespace ancfnet {

namespace {

// dN/dε of the elastic axial force (N) at strain ε, for each axial law of CalcCableAxialForce.
double AxialForceSlope(const CableElementParameters& p, double strain) {
  if (!p.tension_only) return p.axial_stiffness;
  if (p.rope_smoothing_strain > 0.0)
    return p.axial_stiffness * CalcSmoothRopeLaw(strain, p.rope_smoothing_strain).slope;
  return strain > 0.0 ? p.axial_stiffness : 0.0;
}

// Adds scale · (u vᵀ ⊗ I₃) over the four 3×3 blocks: the derivative of Sₓᵀ a with respect to e
// is (ds dsᵀ) ⊗ I₃.
void AddShapeKronecker(const Vector4d& ds, double scale, Matrix12d* k) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      k->block<3, 3>(3 * i, 3 * j).diagonal().array() += scale * ds[i] * ds[j];
}

}  // namespace

CableStepStart CalcCableStepStart(const CableElementParameters& p, const Vector12d& e0) {
  CableStepStart start;
  start.e = e0;
  start.energy = CalcCableStrainEnergy(p, e0);
  const GaussRule& axial = GetGaussRule(p.axial_gauss_points);
  for (int i = 0; i < axial.size; ++i) {
    start.axial_strain[i] = CalcCableStrain(p, e0, axial.points[i]).axial;
    start.axial_energy[i] = CalcCableAxialEnergyDensity(p, start.axial_strain[i]);
  }
  return start;
}

Vector12d CalcCableStepForceCorrection(const CableElementParameters& p, const CableStepStart& start,
                                       const Vector12d& e1, const Vector12d& elastic_force,
                                       Matrix12d* jacobian) {
  const Vector12d& e0 = start.e;
  Vector12d correction = Vector12d::Zero();
  if (jacobian) jacobian->setZero();
  const Vector12d de = e1 - e0;
  if (de.isZero(0.0)) return correction;
  const Vector12d em = 0.5 * (e0 + e1);
  using Matrix34d = Eigen::Matrix<double, 3, 4>;
  const GaussRule& axial = GetGaussRule(p.axial_gauss_points);
  for (int i = 0; i < axial.size; ++i) {
    const HermiteShape shape = CalcHermiteShape(axial.points[i], p.length);
    const Vector3d a1 = Eigen::Map<const Matrix34d>(e1.data()) * shape.ds;
    const Vector3d am = Eigen::Map<const Matrix34d>(em.data()) * shape.ds;
    const double eps0 = start.axial_strain[i];
    const double eps1 = 0.5 * (a1.squaredNorm() - 1.0);
    const double eps_m = 0.5 * (am.squaredNorm() - 1.0);
    // N̄ as a divided difference while it is well above round-off, else the force at the mean
    // strain (equal to second order in ε₁ − ε₀); and ∂N̄/∂ε₁.
    const double change = eps1 - eps0;
    double mean_force = 0.0, dmean_dend = 0.0;
    if (std::abs(change) > 1e-7 * std::max(std::abs(eps0) + std::abs(eps1), 1e-9)) {
      mean_force = (CalcCableAxialEnergyDensity(p, eps1) - start.axial_energy[i]) / change;
      dmean_dend = (CalcCableAxialForce(p, eps1) - mean_force) / change;
    } else {
      mean_force = CalcCableAxialForce(p, 0.5 * (eps0 + eps1));
      dmean_dend = 0.5 * AxialForceSlope(p, 0.5 * (eps0 + eps1));
    }
    const double weight = axial.weights[i] * p.length;
    const double excess = mean_force - CalcCableAxialForce(p, eps_m);
    const Vector12d bm = DistributeForce(shape.ds, am);
    correction += (weight * excess) * bm;
    if (!jacobian) continue;
    // With respect to the midpoint e_m (e₁ = 2 e_m − e₀): ∂ε₁/∂e_m = 2 Sₓᵀ a₁, ∂ε_m/∂e_m = Sₓᵀ a_m.
    const Vector12d b1 = DistributeForce(shape.ds, a1);
    jacobian->noalias() +=
        weight * bm * (2.0 * dmean_dend * b1 - AxialForceSlope(p, eps_m) * bm).transpose();
    AddShapeKronecker(shape.ds, weight * excess, jacobian);
  }
  // The bending energy's share of the error (and round-off of the axial part), along Δe; left
  // out of the Jacobian (it is of third order in Δe).
  const double u0 = start.energy;
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
