#include "ancfnet/elements/ancf_beam.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {
namespace {

// L = 0.5 m and stiffnesses of similar size but all different, so that a term given the wrong
// stiffness shows up.
BeamElementParameters MakeParameters() {
  return {.length = 0.5,
          .axial_stiffness = 400.0,
          .shear_stiffness_y = 150.0,
          .shear_stiffness_z = 120.0,
          .torsional_stiffness = 7.0,
          .bending_stiffness_y = 9.0,
          .bending_stiffness_z = 11.0,
          .section_normal_stiffness = 300.0,
          .section_shear_stiffness = 90.0,
          .mass_per_length = 2.0,
          .rotary_inertia_y = 0.03,
          .rotary_inertia_z = 0.05};
}

// Straight element along the unit vector t with directors (d2, d3), moved by rotation R and
// translation p.
Vector24d StraightElement(double length, const Matrix3d& rotation, const Vector3d& p) {
  Vector24d e;
  const Vector3d t = rotation.col(0), d2 = rotation.col(1), d3 = rotation.col(2);
  e << p, t, d2, d3, p + length * t, t, d2, d3;
  return e;
}

// A generic stretched, sheared, bent, twisted element with distorted directors.
Vector24d DeformedElement() {
  Vector24d e = StraightElement(0.5, Matrix3d::Identity(), Vector3d::Zero());
  Vector24d delta;
  delta << 0.01, -0.02, 0.03, 0.05, 0.2, -0.1, -0.15, 0.02, 0.04, 0.03, 0.1, -0.05,  //
      0.03, 0.11, -0.07, -0.1, 0.15, 0.2, 0.05, -0.04, 0.2, -0.02, -0.2, 0.06;
  return e + delta;
}

Vector24d Force(const BeamElementParameters& p, const Vector24d& e) {
  Vector24d f;
  CalcBeamInternalForce(p, e, Vector24d::Zero(), {.force = &f});
  return f;
}

TEST(AncfBeam, ForceIsGradientOfStrainEnergy) {
  const BeamElementParameters p = MakeParameters();
  const Vector24d e = DeformedElement();
  const Vector24d f = Force(p, e);
  const double h = 1e-6;
  for (int i = 0; i < 24; ++i) {
    Vector24d ep = e, em = e;
    ep[i] += h;
    em[i] -= h;
    const double fd = (CalcBeamStrainEnergy(p, ep) - CalcBeamStrainEnergy(p, em)) / (2 * h);
    EXPECT_NEAR(f[i], fd, 1e-6 * f.norm()) << "coordinate " << i;
  }
}

TEST(AncfBeam, StiffnessMatchesFiniteDifferences) {
  const BeamElementParameters p = MakeParameters();
  const Vector24d e = DeformedElement();
  Vector24d f;
  Matrix24d k;
  CalcBeamInternalForce(p, e, Vector24d::Zero(), {.force = &f, .stiffness = &k});
  EXPECT_LT((f - Force(p, e)).norm(), 1e-12 * f.norm());
  Matrix24d k_fd;
  const double h = 1e-6;
  for (int j = 0; j < 24; ++j) {
    Vector24d ep = e, em = e;
    ep[j] += h;
    em[j] -= h;
    k_fd.col(j) = (Force(p, ep) - Force(p, em)) / (2 * h);
  }
  EXPECT_LT((k - k_fd).norm(), 1e-6 * k.norm()) << "stiffness\n" << k - k_fd;
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
}

TEST(AncfBeam, RigidMotionIsFreeOfStrain) {
  const BeamElementParameters p = MakeParameters();
  const Matrix3d rotation =
      Eigen::AngleAxisd(1.1, Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Vector24d e = StraightElement(p.length, rotation, Vector3d(1.0, -2.0, 0.5));
  EXPECT_LT(CalcBeamStrainEnergy(p, e), 1e-24);
  EXPECT_LT(Force(p, e).norm(), 1e-12);
}

TEST(AncfBeam, StraightElementHasOnlyTheSixRigidZeroEnergyModes) {
  // A zero-energy mode beyond the rigid ones would be a spurious (hourglass) mode: this checks
  // that the assumed shear strain leaves none (docs/theory.md, "Locking").
  const BeamElementParameters p = MakeParameters();
  Matrix24d k;
  CalcBeamInternalForce(p, StraightElement(p.length, Matrix3d::Identity(), Vector3d::Zero()),
                        Vector24d::Zero(), {.stiffness = &k});
  const Eigen::SelfAdjointEigenSolver<Matrix24d> eig(k);
  const auto& lambda = eig.eigenvalues();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-9 * lambda[23]) << i;
  EXPECT_GT(lambda[6], 1e-4 * lambda[23]);
}

TEST(AncfBeam, UniformTwistStoresTorsionEnergy) {
  // Directors of node B turned by φ about the axis: U = ½ GJ φ²/L to O(φ²).
  const BeamElementParameters p = MakeParameters();
  const double phi = 1e-3;
  const Matrix3d turn = Eigen::AngleAxisd(phi, Vector3d::UnitX()).toRotationMatrix();
  Vector24d e = StraightElement(p.length, Matrix3d::Identity(), Vector3d::Zero());
  e.segment<3>(18) = turn.col(1);
  e.segment<3>(21) = turn.col(2);
  const double expected = 0.5 * p.torsional_stiffness * phi * phi / p.length;
  EXPECT_NEAR(CalcBeamStrainEnergy(p, e), expected, 1e-4 * expected);
}

TEST(AncfBeam, ConstantCurvatureStoresBendingEnergy) {
  // Centre line on a circle of curvature κ about d₃, sections normal to it: U = ½ EI_z κ² L to
  // O(κ²), with no shear.
  const BeamElementParameters p = MakeParameters();
  const double kappa = 1e-3;
  const double angle = kappa * p.length;
  const Vector3d end(std::sin(angle) / kappa, (1.0 - std::cos(angle)) / kappa, 0.0);
  const Vector3d t_end(std::cos(angle), std::sin(angle), 0.0);
  Vector24d e;
  e << Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(),  //
      end, t_end, Vector3d::UnitZ().cross(t_end), Vector3d::UnitZ();
  const double expected = 0.5 * p.bending_stiffness_z * kappa * kappa * p.length;
  EXPECT_NEAR(CalcBeamStrainEnergy(p, e), expected, 1e-3 * expected);
}

TEST(AncfBeam, AxisIsInterpolatedLikeTheCableFromTheFirstSixNodalCoordinates) {
  // A beam node's (r, r_x) are a cable node's (r, r'): both elements share the centre line, so
  // a mesh can join them through those coordinates.
  constexpr int kAxisBlocks[4] = {0, 1, 4, 5};
  for (const double xi : {0.0, 0.2113, 0.5, 0.9}) {
    const BeamLocalMap map = MakeBeamLocalMap(xi, 0.7);
    const HermiteShape cable = CalcHermiteShape(xi, 0.7);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(map.position[kAxisBlocks[i]], cable.s[i]);
      EXPECT_EQ(map.b(kSlope, kAxisBlocks[i]), cable.ds[i]);
      EXPECT_EQ(map.b(kCurvatureVector, kAxisBlocks[i]), cable.dds[i]);
    }
  }
}

// Damping times that differ, on the parameters above, and a rate that strains every term.
BeamElementParameters MakeDampedParameters() {
  BeamElementParameters p = MakeParameters();
  p.axial_damping_time = 0.03;
  p.bending_damping_time = 0.07;
  return p;
}

Vector24d StrainRate() {
  Vector24d e_dot;
  for (int i = 0; i < 24; ++i) e_dot[i] = std::sin(1.7 * i + 0.4);
  return e_dot;
}

Vector24d DampedForce(const BeamElementParameters& p, const Vector24d& e, const Vector24d& e_dot) {
  Vector24d f;
  CalcBeamInternalForce(p, e, e_dot, {.force = &f});
  return f;
}

TEST(AncfBeam, KelvinVoigtJacobiansMatchFiniteDifferences) {
  const BeamElementParameters p = MakeDampedParameters();
  const Vector24d e = DeformedElement();
  const Vector24d e_dot = StrainRate();
  Vector24d f, f_visc;
  Matrix24d k, c;
  CalcBeamInternalForce(p, e, e_dot,
                        {.force = &f, .viscous_force = &f_visc, .stiffness = &k, .damping = &c});
  // The viscous part is what the rate adds to the elastic force, and is not small here.
  EXPECT_LT((f - f_visc - Force(p, e)).norm(), 1e-12 * f.norm());
  EXPECT_GT(f_visc.norm(), 0.1 * f.norm());
  Matrix24d k_fd, c_fd;
  const double h = 1e-6;
  for (int j = 0; j < 24; ++j) {
    Vector24d ep = e, em = e, vp = e_dot, vm = e_dot;
    ep[j] += h;
    em[j] -= h;
    vp[j] += h;
    vm[j] -= h;
    k_fd.col(j) = (DampedForce(p, ep, e_dot) - DampedForce(p, em, e_dot)) / (2 * h);
    c_fd.col(j) = (DampedForce(p, e, vp) - DampedForce(p, e, vm)) / (2 * h);
  }
  EXPECT_LT((k - k_fd).norm(), 1e-6 * k.norm()) << "stiffness\n" << k - k_fd;
  EXPECT_LT((c - c_fd).norm(), 1e-6 * c.norm()) << "damping\n" << c - c_fd;
  // Asked alone, the damping matrix is the same.
  Matrix24d c_alone;
  CalcBeamInternalForce(p, e, e_dot, {.damping = &c_alone});
  EXPECT_LT((c_alone - c).norm(), 1e-12 * c.norm());
}

TEST(AncfBeam, KelvinVoigtDissipatesAndRigidMotionDoesNot) {
  // ėᵀ Q_visc = Σ τᵢ kᵢ ṡᵢ² ≥ 0 for any rate; a rigid rotation of a straight element changes no
  // strain, so it is free of viscous force.
  const BeamElementParameters p = MakeDampedParameters();
  Vector24d f_visc;
  CalcBeamInternalForce(p, DeformedElement(), StrainRate(), {.viscous_force = &f_visc});
  EXPECT_GT(StrainRate().dot(f_visc), 0.0);
  const Vector24d e = StraightElement(p.length, Matrix3d::Identity(), Vector3d::Zero());
  const Vector3d omega(0.3, -1.2, 0.8);
  Vector24d spin;
  for (int b = 0; b < 8; ++b) spin.segment<3>(3 * b) = omega.cross(Vector3d(e.segment<3>(3 * b)));
  CalcBeamInternalForce(p, e, spin, {.viscous_force = &f_visc});
  EXPECT_LT(f_visc.norm(), 1e-12);
}

TEST(AncfBeam, MassMatrixGivesMassAndRotaryInertiaOfRigidMotions) {
  const BeamElementParameters p = MakeParameters();
  const Matrix24d m = CalcBeamMassMatrix(p);
  const double length = p.length;
  const Vector24d e = StraightElement(length, Matrix3d::Identity(), Vector3d::Zero());
  // Velocity of the rigid motion ω × (r − 0) of every block (positions and gradients alike).
  const auto rigid_velocity = [&](const Vector3d& v, const Vector3d& omega) {
    Vector24d e_dot;
    for (int node = 0; node < 2; ++node) {
      e_dot.segment<3>(12 * node) = v + omega.cross(e.segment<3>(12 * node));
      for (int g = 1; g < 4; ++g)
        e_dot.segment<3>(12 * node + 3 * g) = omega.cross(e.segment<3>(12 * node + 3 * g));
    }
    return e_dot;
  };
  const double mass = p.mass_per_length * length;
  const Vector24d translation = rigid_velocity(Vector3d(0.3, -0.4, 1.2), Vector3d::Zero());
  EXPECT_NEAR(translation.dot(m * translation), mass * (0.09 + 0.16 + 1.44), 1e-13);
  // About the axis: the polar mass moment ρ(I_y + I_z) L.
  const Vector24d spin = rigid_velocity(Vector3d::Zero(), Vector3d::UnitX());
  EXPECT_NEAR(spin.dot(m * spin), (p.rotary_inertia_y + p.rotary_inertia_z) * length, 1e-14);
  // About z through node A: ρA L³/3 + ρI_z L.
  const Vector24d swing = rigid_velocity(Vector3d::Zero(), Vector3d::UnitZ());
  EXPECT_NEAR(swing.dot(m * swing),
              p.mass_per_length * std::pow(length, 3) / 3.0 + p.rotary_inertia_z * length, 1e-14);
  EXPECT_LT((m - m.transpose()).norm(), 1e-15);
}

}  // namespace
}  // namespace ancfnet
