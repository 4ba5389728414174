// The element-level pieces of the tension recovery: the tension N λ of the axial law, the
// Gauss-point polynomial, the midpoint force and the interpolation between stations.

#include "ancfnet/elements/ancf_cable_tension.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/common/quadrature.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/elements/test/cable_element_fixtures.hpp"

namespace ancfnet {
namespace {

CableElementParameters MakeParameters() { return test::MakeCableTestParameters(); }

// Nodal coordinates of a straight element from the origin along `dir` (unit), stretched by λ.
Vector12d StraightElement(const Vector3d& dir, double length, double stretch) {
  return test::StraightElement(Vector3d::Zero(), dir, length, stretch);
}

// A bent, stretched configuration with no symmetry.
Vector12d BentElement() {
  Vector12d e;
  e << 0.01, -0.02, 0.03, 0.95, 0.2, -0.1, 0.23, 0.05, -0.04, 0.7, 0.6, 0.3;
  return e;
}

Vector3d UnitTangent(const CableElementParameters& p, const Vector12d& e, double xi) {
  return (Eigen::Map<const Eigen::Matrix<double, 3, 4>>(e.data()) *
          CalcHermiteShape(xi, p.length).ds)
      .normalized();
}

// Uniform stretch: the section force is N r' = N λ t everywhere, for every axial law.
TEST(AncfCableTension, UniformStretchGivesTheSectionForceEverywhere) {
  for (int law = 0; law < 3; ++law) {
    CableElementParameters p = MakeParameters();
    p.tension_only = law > 0;
    p.rope_smoothing_strain = law == 2 ? 1e-3 : 0.0;
    for (double stretch : {0.98, 1.0004, 1.02}) {
      const Vector3d dir = Vector3d(1, 2, -0.5).normalized();
      const Vector12d e = StraightElement(dir, p.length, stretch);
      const double strain = 0.5 * (stretch * stretch - 1.0);
      const double tension = CalcCableAxialForce(p, strain) * stretch;
      EXPECT_DOUBLE_EQ(CalcCableTension(p, strain), tension);
      const Vector3d midpoint = CalcCableMidpointForce(p, e);
      EXPECT_LT((midpoint - tension * dir).norm(), 1e-9 * p.axial_stiffness) << law;
      const CableStationForces forces{midpoint, midpoint, midpoint};
      for (double xi : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        EXPECT_NEAR(CalcCableGaussPointTension(p, e, xi), tension, 1e-9 * p.axial_stiffness);
        EXPECT_NEAR(CalcCableStationTension(p, e, forces, xi), tension, 1e-9 * p.axial_stiffness);
      }
    }
  }
}

// The polynomial passes through the Gauss-point tensions, for 1 to 5 points.
TEST(AncfCableTension, GaussPointPolynomialInterpolatesTheGaussPoints) {
  CableElementParameters p = MakeParameters();
  const Vector12d e = BentElement();
  for (int n = 1; n <= 5; ++n) {
    p.axial_gauss_points = n;
    const GaussRule& rule = GetGaussRule(n);
    for (int i = 0; i < rule.size; ++i) {
      const double expected = CalcCableTension(p, CalcCableStrain(p, e, rule.points[i]).axial);
      EXPECT_NEAR(CalcCableGaussPointTension(p, e, rule.points[i]), expected,
                  1e-12 * p.axial_stiffness)
          << n << " points";
    }
  }
  p.axial_gauss_points = 1;  // degree 0: the constant
  EXPECT_DOUBLE_EQ(CalcCableGaussPointTension(p, e, 0.0), CalcCableGaussPointTension(p, e, 1.0));
}

// F_M = Q_{r_B} = −Q_{r_A} of the internal force without its Kelvin–Voigt part.
TEST(AncfCableTension, MidpointForceIsTheElasticEndForce) {
  CableElementParameters p = MakeParameters();
  p.axial_damping_time = 0.01;
  const Vector12d e = BentElement();
  Vector12d f;
  CalcCableInternalForce(p, e, Vector12d::Zero(), {.force = &f});
  const Vector3d midpoint = CalcCableMidpointForce(p, e);
  EXPECT_TRUE(midpoint.isApprox(f.segment<3>(6), 1e-14));
  EXPECT_LT((midpoint + f.segment<3>(0)).norm(), 1e-9 * midpoint.norm());
}

// Linear between the stations on each half, projected on the unit tangent; ropes never push.
TEST(AncfCableTension, StationTensionInterpolatesOnEachHalf) {
  CableElementParameters p = MakeParameters();
  const Vector12d e = BentElement();
  const CableStationForces forces{Vector3d(3, 1, 0), Vector3d(5, -1, 2), Vector3d(4, 2, 2)};
  const auto expected = [&](const Vector3d& force, double xi) {
    return force.dot(UnitTangent(p, e, xi));
  };
  EXPECT_NEAR(CalcCableStationTension(p, e, forces, 0.0), expected(forces.start, 0.0), 1e-12);
  EXPECT_NEAR(CalcCableStationTension(p, e, forces, 0.5), expected(forces.middle, 0.5), 1e-12);
  EXPECT_NEAR(CalcCableStationTension(p, e, forces, 1.0), expected(forces.end, 1.0), 1e-12);
  EXPECT_NEAR(CalcCableStationTension(p, e, forces, 0.2),
              expected(0.6 * forces.start + 0.4 * forces.middle, 0.2), 1e-12);
  EXPECT_NEAR(CalcCableStationTension(p, e, forces, 0.9),
              expected(0.2 * forces.middle + 0.8 * forces.end, 0.9), 1e-12);
  const CableStationForces pushing{-forces.start, -forces.middle, -forces.end};
  EXPECT_LT(CalcCableStationTension(p, e, pushing, 0.5), 0.0);
  p.tension_only = true;
  EXPECT_EQ(CalcCableStationTension(p, e, pushing, 0.5), 0.0);
}

}  // namespace
}  // namespace ancfnet
