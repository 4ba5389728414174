#include "ancfnet/elements/ancf_cable_step_force.hpp"

#include <gtest/gtest.h>

#include "ancfnet/elements/test/cable_element_fixtures.hpp"

namespace ancfnet {
namespace {

// Two configurations a large step apart: stretched and bent at the start, compressed in part
// and bent the other way at the end (the midpoint strain then differs from the mean strain).
Vector12d Start() {
  Vector12d e;
  e << 0.0, 0.0, 0.0, 1.02, 0.05, 0.0, 0.255, 0.01, 0.0, 1.01, -0.04, 0.02;
  return e;
}
Vector12d End() {
  Vector12d e;
  e << 0.01, -0.005, 0.002, 0.97, 0.12, -0.03, 0.24, 0.03, 0.01, 1.0, 0.08, 0.01;
  return e;
}

Vector12d ElasticForce(const CableElementParameters& p, const Vector12d& e) {
  Vector12d f;
  CalcCableInternalForce(p, e, Vector12d::Zero(), {.force = &f});
  return f;
}

// The work of Q_el(e_m) + ΔQ over the step, against the change of the strain energy.
double WorkError(const CableElementParameters& p, const Vector12d& e0, const Vector12d& e1) {
  const Vector12d force = ElasticForce(p, 0.5 * (e0 + e1));
  const Vector12d step = CalcCableStepForceCorrection(p, e0, e1, force) + force;
  return (e1 - e0).dot(step) - (CalcCableStrainEnergy(p, e1) - CalcCableStrainEnergy(p, e0));
}

TEST(CableStepForce, WorkEqualsEnergyChangeForEveryAxialLaw) {
  CableElementParameters p = test::MakeCableTestParameters();
  const double scale = CalcCableStrainEnergy(p, Start()) + CalcCableStrainEnergy(p, End());
  // The plain midpoint force misses the energy change by a visible amount here.
  const Vector12d mid_force = ElasticForce(p, 0.5 * (Start() + End()));
  const double midpoint_error = (End() - Start()).dot(mid_force) -
                                (CalcCableStrainEnergy(p, End()) - CalcCableStrainEnergy(p, Start()));
  EXPECT_GT(std::abs(midpoint_error), 1e-4 * scale);
  EXPECT_NEAR(WorkError(p, Start(), End()), 0.0, 1e-12 * scale);
  p.tension_only = true;
  EXPECT_NEAR(WorkError(p, Start(), End()), 0.0, 1e-12 * scale);
  p.rope_smoothing_strain = 0.01;
  EXPECT_NEAR(WorkError(p, Start(), End()), 0.0, 1e-12 * scale);
  p.bending_model = BendingModel::kSecondDerivative;
  EXPECT_NEAR(WorkError(p, Start(), End()), 0.0, 1e-12 * scale);
}

// With the simple bending model the energy is exact without the bending term along Δe, and the
// axial correction is a sum of Sₓᵀ r' terms: it has no net force, so momentum is kept.
TEST(CableStepForce, AxialCorrectionHasNoNetForce) {
  CableElementParameters p = test::MakeCableTestParameters();
  p.bending_model = BendingModel::kSecondDerivative;
  const Vector12d force = ElasticForce(p, 0.5 * (Start() + End()));
  const Vector12d correction = CalcCableStepForceCorrection(p, Start(), End(), force);
  EXPECT_GT(correction.norm(), 1e-3 * force.norm());
  const Vector3d net = correction.segment<3>(0) + correction.segment<3>(6);
  EXPECT_LT(net.norm(), 1e-12 * correction.norm());
}

// ∂ΔQ/∂e_m (e₁ = 2 e_m − e₀) against central differences, for the linear and the smooth rope
// law (simple bending: the correction is all axial).
TEST(CableStepForce, JacobianMatchesFiniteDifferences) {
  CableElementParameters p = test::MakeCableTestParameters();
  p.bending_model = BendingModel::kSecondDerivative;
  for (bool rope : {false, true}) {
    p.tension_only = rope;
    p.rope_smoothing_strain = rope ? 0.01 : 0.0;
    const Vector12d e0 = Start();
    const Vector12d em = 0.5 * (Start() + End());
    const auto correction = [&](const Vector12d& mid) {
      return CalcCableStepForceCorrection(p, e0, 2.0 * mid - e0, ElasticForce(p, mid));
    };
    Matrix12d jacobian;
    CalcCableStepForceCorrection(p, e0, 2.0 * em - e0, ElasticForce(p, em), &jacobian);
    Matrix12d numeric;
    const double h = 1e-6;
    for (int j = 0; j < 12; ++j) {
      Vector12d plus = em, minus = em;
      plus[j] += h;
      minus[j] -= h;
      numeric.col(j) = (correction(plus) - correction(minus)) / (2.0 * h);
    }
    EXPECT_GT(jacobian.norm(), 1e-3 * p.axial_stiffness);
    EXPECT_LT((jacobian - numeric).norm(), 1e-6 * jacobian.norm()) << "rope " << rope;
  }
}

TEST(CableStepForce, VanishesForAStepThatDoesNotMove) {
  const CableElementParameters p = test::MakeCableTestParameters();
  const Vector12d force = ElasticForce(p, Start());
  EXPECT_EQ(CalcCableStepForceCorrection(p, Start(), Start(), force), Vector12d::Zero());
}

// For a small step the discrete gradient approaches the force at the midpoint (second order).
TEST(CableStepForce, ConvergesToTheMidpointForceAsTheStepShrinks) {
  const CableElementParameters p = test::MakeCableTestParameters();
  double previous = 0.0;
  for (double scale : {1e-2, 1e-3}) {
    const Vector12d e1 = Start() + scale * (End() - Start());
    const Vector12d force = ElasticForce(p, 0.5 * (Start() + e1));
    const double size = CalcCableStepForceCorrection(p, Start(), e1, force).norm() / force.norm();
    if (previous > 0.0) {
      EXPECT_LT(size, 0.02 * previous);  // ∝ Δe²: 100× smaller
    }
    previous = size;
  }
}

}  // namespace
}  // namespace ancfnet
