// The tension of the ANCF beam element (elements/ancf_beam_tension.hpp): the section's normal
// force N = EA Γ₁ of a uniformly stretched element, read at the Gauss points and from the
// element's resultant force, and a uniformly sheared element, whose resultant force is all shear
// and whose normal force is zero although the force has a component along the tangent.

#include "ancfnet/elements/ancf_beam_tension.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace ancfnet {
namespace {

BeamElementParameters Parameters() {
  return {.length = 0.4,
          .axial_stiffness = 500.0,
          .shear_stiffness_y = 150.0,
          .shear_stiffness_z = 120.0,
          .torsional_stiffness = 7.0,
          .bending_stiffness_y = 9.0,
          .bending_stiffness_z = 11.0,
          .section_normal_stiffness = 300.0,
          .section_shear_stiffness = 90.0,
          .mass_per_length = 2.0};
}

// A turned element (frame t, d₂, d₃ = columns of `rotation`) whose axis has the uniform slope
// r' = `slope` (in the turned frame's components), with undeformed directors.
Vector24d UniformElement(const BeamElementParameters& p, const Matrix3d& rotation,
                         const Vector3d& slope) {
  const Vector3d r_x = rotation * slope, d2 = rotation.col(1), d3 = rotation.col(2);
  const Vector3d p_A(0.3, -0.2, 0.1);
  Vector24d e;
  e << p_A, r_x, d2, d3, p_A + p.length * r_x, r_x, d2, d3;
  return e;
}

Matrix3d Turned() {
  return Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
}

TEST(AncfBeamTension, UniformStretchReadsEaTimesTheStrain) {
  const BeamElementParameters p = Parameters();
  const double strain = 0.02;
  const Vector24d e = UniformElement(p, Turned(), Vector3d(1.0 + strain, 0.0, 0.0));
  const double expected = p.axial_stiffness * strain;  // Γ₁ = ε, N = EA Γ₁
  for (double xi : {0.0, 0.3, 0.5, 1.0}) {
    EXPECT_NEAR(CalcBeamAxialStrain(p, e, xi), strain, 1e-14);
    EXPECT_NEAR(CalcBeamGaussPointAxialForce(p, e, xi), expected, 1e-12 * expected);
    EXPECT_LT((CalcBeamSectionNormal(e, xi) - Turned().col(0)).norm(), 1e-14);
  }
  const Vector3d midpoint = CalcBeamMidpointForce(p, e);
  EXPECT_LT((midpoint - expected * Turned().col(0)).norm(), 1e-12 * expected);
  const CableStationForces forces{midpoint, midpoint, midpoint};
  for (double xi : {0.0, 0.25, 0.5, 0.9})
    EXPECT_NEAR(CalcBeamStationTension(e, forces, xi), expected, 1e-12 * expected);
  // The centre line read as a cable (Green strain, N λ) would give EA (ε + ε²/2)(1 + ε),
  // 3 % more: the beam's measure is not the cable's.
}

TEST(AncfBeamTension, UniformShearIsNoNormalForce) {
  const BeamElementParameters p = Parameters();
  const double shear = 0.1;
  // r' = t + γ d₂: Γ₁ = r'·(d₂ × d₃) − 1 = 0, Γ₂ = γ; the section force is k_yGA γ d₂.
  const Vector24d e = UniformElement(p, Turned(), Vector3d(1.0, shear, 0.0));
  const Vector3d midpoint = CalcBeamMidpointForce(p, e);
  const double shear_force = p.shear_stiffness_y * shear;
  EXPECT_LT((midpoint - shear_force * Turned().col(1)).norm(), 1e-12 * shear_force);
  const CableStationForces forces{midpoint, midpoint, midpoint};
  // Along the tangent the force reads k_yGA γ² / √(1 + γ²) = 1.49 N; along the normal, zero.
  for (double xi : {0.0, 0.5, 1.0}) {
    EXPECT_NEAR(CalcBeamStationTension(e, forces, xi), 0.0, 1e-12 * shear_force);
    EXPECT_NEAR(CalcBeamGaussPointAxialForce(p, e, xi), 0.0, 1e-12 * shear_force);
  }
}

}  // namespace
}  // namespace ancfnet
