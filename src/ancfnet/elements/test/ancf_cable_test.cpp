#include "ancfnet/elements/ancf_cable.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/elements/test/cable_element_fixtures.hpp"

namespace ancfnet {
namespace {

CableElementParameters MakeParameters() { return test::MakeCableTestParameters(); }

using test::StraightElement;

// A generic bent, stretched and twisted configuration (no symmetry to hide sign errors).
Vector12d BentElement() {
  Vector12d e;
  e << 0.01, -0.02, 0.03, 0.95, 0.2, -0.1, 0.23, 0.05, -0.04, 0.7, 0.6, 0.3;
  return e;
}

Vector12d Velocity() {
  Vector12d v;
  v << 0.3, -0.1, 0.2, 0.5, -0.7, 0.1, -0.2, 0.4, 0.6, -0.3, 0.2, 0.9;
  return v;
}

Vector12d Force(const CableElementParameters& p, const Vector12d& e, const Vector12d& v) {
  Vector12d f;
  CalcCableInternalForce(p, e, v, {.force = &f});
  return f;
}

TEST(AncfCable, ForceIsGradientOfStrainEnergy) {
  const CableElementParameters p = MakeParameters();
  const Vector12d e = BentElement();
  const Vector12d f = Force(p, e, Vector12d::Zero());
  const double h = 1e-6;
  for (int i = 0; i < 12; ++i) {
    Vector12d ep = e, em = e;
    ep[i] += h;
    em[i] -= h;
    const double fd = (CalcCableStrainEnergy(p, ep) - CalcCableStrainEnergy(p, em)) / (2 * h);
    EXPECT_NEAR(f[i], fd, 1e-6 * f.norm()) << "coordinate " << i;
  }
}

void ExpectJacobiansMatchFiniteDifferences(const CableElementParameters& p, const Vector12d& e,
                                           const Vector12d& v) {
  Matrix12d k, c;
  Vector12d f;
  CalcCableInternalForce(p, e, v, {.force = &f, .stiffness = &k, .damping = &c});
  Matrix12d k_fd, c_fd;
  const double h = 1e-6;
  for (int j = 0; j < 12; ++j) {
    Vector12d ep = e, em = e, vp = v, vm = v;
    ep[j] += h;
    em[j] -= h;
    vp[j] += h;
    vm[j] -= h;
    k_fd.col(j) = (Force(p, ep, v) - Force(p, em, v)) / (2 * h);
    c_fd.col(j) = (Force(p, e, vp) - Force(p, e, vm)) / (2 * h);
  }
  EXPECT_LT((k - k_fd).norm(), 1e-6 * k.norm()) << "stiffness\n" << k - k_fd;
  if (c.norm() > 0)
    EXPECT_LT((c - c_fd).norm(), 1e-6 * c.norm()) << "damping\n" << c - c_fd;
  else
    EXPECT_LT(c_fd.norm(), 1e-9);
}

TEST(AncfCable, StiffnessMatchesFiniteDifferences) {
  ExpectJacobiansMatchFiniteDifferences(MakeParameters(), BentElement(), Vector12d::Zero());
}

TEST(AncfCable, KelvinVoigtJacobiansMatchFiniteDifferences) {
  CableElementParameters p = MakeParameters();
  p.axial_damping_time = 0.01;
  p.bending_damping_time = 0.02;
  ExpectJacobiansMatchFiniteDifferences(p, BentElement(), Velocity());
}

TEST(AncfCable, KelvinVoigtJacobiansMatchFiniteDifferencesOnAnArc) {
  // A plane arc bent out of its plane by the velocity: the case where the magnitude and the
  // direction of the curvature change together.
  CableElementParameters p = MakeParameters();
  p.axial_damping_time = 0.01;
  p.bending_damping_time = 0.03;
  const double radius = 2.0 * p.length / M_PI;
  Vector12d e;
  e << 0, 0, 0, 1, 0, 0, radius, radius, 0, 0, 1.02, 0;
  ExpectJacobiansMatchFiniteDifferences(p, e, Velocity());
}

TEST(AncfCable, SmoothRopeLawMatchesFiniteDifferencesAndTheExactLaw) {
  CableElementParameters p = MakeParameters();
  p.tension_only = true;
  p.rope_smoothing_strain = 0.02;  // large, so that the smooth branch is exercised at all points
  p.axial_damping_time = 0.01;
  ExpectJacobiansMatchFiniteDifferences(p, BentElement(), Velocity());
  p.axial_damping_time = 0.0;
  const Vector12d e = BentElement();
  const Vector12d f = Force(p, e, Vector12d::Zero());
  for (int i = 0; i < 12; ++i) {
    Vector12d ep = e, em = e;
    ep[i] += 1e-6;
    em[i] -= 1e-6;
    EXPECT_NEAR(f[i], (CalcCableStrainEnergy(p, ep) - CalcCableStrainEnergy(p, em)) / 2e-6,
                1e-6 * f.norm());
  }
  // Far from the band the smooth law is the exact one: 1 % stretch with ε_s = 1e-5.
  p.rope_smoothing_strain = 1e-5;
  p.bending_stiffness = 0.0;
  const Vector12d stretched = StraightElement(Vector3d::Zero(), Vector3d::UnitX(), p.length, 1.01);
  CableElementParameters exact = p;
  exact.rope_smoothing_strain = 0.0;
  EXPECT_NEAR(Force(p, stretched, Vector12d::Zero())[6],
              Force(exact, stretched, Vector12d::Zero())[6], 1e-7 * p.axial_stiffness);
}

TEST(AncfCable, SecondDerivativeBendingMatchesFiniteDifferences) {
  CableElementParameters p = MakeParameters();
  p.bending_model = BendingModel::kSecondDerivative;
  p.axial_damping_time = 0.01;
  p.bending_damping_time = 0.02;
  ExpectJacobiansMatchFiniteDifferences(p, BentElement(), Velocity());
  // Force = gradient of the energy, and regular where |r'| vanishes.
  p.bending_damping_time = p.axial_damping_time = 0.0;
  Vector12d collapsed = BentElement();
  collapsed.segment<3>(3).setZero();
  const Vector12d f = Force(p, collapsed, Vector12d::Zero());
  EXPECT_TRUE(f.allFinite());
  for (int i = 0; i < 12; ++i) {
    Vector12d ep = collapsed, em = collapsed;
    ep[i] += 1e-6;
    em[i] -= 1e-6;
    EXPECT_NEAR(f[i], (CalcCableStrainEnergy(p, ep) - CalcCableStrainEnergy(p, em)) / 2e-6,
                1e-6 * f.norm());
  }
}

TEST(AncfCable, TensionOnlyJacobiansMatchFiniteDifferences) {
  CableElementParameters p = MakeParameters();
  p.tension_only = true;
  p.axial_damping_time = 0.01;
  ExpectJacobiansMatchFiniteDifferences(p, BentElement(), Velocity());
}

TEST(AncfCable, RigidBodyMotionGivesNoElasticForce) {
  const CableElementParameters p = MakeParameters();
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Vector12d e =
      StraightElement(Vector3d(1.0, 2.0, -3.0), rotation * Vector3d::UnitX(), p.length, 1.0);
  // Rigid velocity: ω × r at every point, and ω × r' for the slopes.
  const Vector3d omega(0.3, -0.8, 1.1);
  Vector12d v;
  for (int node = 0; node < 4; ++node)
    v.segment<3>(3 * node) = omega.cross(Vector3d(e.segment<3>(3 * node)));
  for (int node : {0, 2}) v.segment<3>(3 * node) += Vector3d(0.4, 0.1, -0.2);
  CableElementParameters damped = p;
  damped.axial_damping_time = 0.05;
  damped.bending_damping_time = 0.05;
  EXPECT_LT(Force(damped, e, v).norm(), 1e-9 * p.axial_stiffness);
  EXPECT_NEAR(CalcCableStrainEnergy(p, e), 0.0, 1e-12);
}

TEST(AncfCable, BentElementInRigidRotationDissipatesAlmostNothing) {
  // Bending damping acts on the rate of the curvature's magnitude once the element is bent:
  // spinning a bent element (ė = ω × e for positions and slopes alike) dissipates a fraction
  // κ_ε²/κ² ≈ 4e-7 of what damping of the curvature vector's rate, EI τ |ω × k|² L, would,
  // while bending it further dissipates.
  CableElementParameters p = MakeParameters();
  p.axial_damping_time = 0.05;
  p.bending_damping_time = 0.05;
  Vector12d e;  // a quarter-circle arc of radius R in the xy-plane: κ = 1/R, k along z
  const double radius = 2.0 * p.length / M_PI;
  e << 0, 0, 0, 1, 0, 0, radius, radius, 0, 0, 1, 0;
  const Vector3d omega(0.3, -0.8, 1.1);
  Vector12d v;
  for (int node = 0; node < 4; ++node)
    v.segment<3>(3 * node) = omega.cross(Vector3d(e.segment<3>(3 * node)));
  Vector12d viscous;
  CalcCableInternalForce(p, e, v, {.viscous_force = &viscous});
  const double vector_rate_power = p.bending_stiffness * p.bending_damping_time *
                                   omega.cross(Vector3d::UnitZ() / radius).squaredNorm() * p.length;
  EXPECT_LT(std::abs(viscous.dot(v)), 1e-5 * vector_rate_power);
  Vector12d bend = Vector12d::Zero();  // tip slope turning further: the curvature grows
  bend.segment<3>(9) = Vector3d(-0.2, 0.0, 0.0);
  CalcCableInternalForce(p, e, bend, {.viscous_force = &viscous});
  EXPECT_GT(viscous.dot(bend), 0.0);  // positive dissipated power
}

TEST(AncfCable, TensionOnlyCarriesNoCompression) {
  CableElementParameters p = MakeParameters();
  p.tension_only = true;
  p.bending_stiffness = 0.0;
  const Vector12d compressed = StraightElement(Vector3d::Zero(), Vector3d::UnitX(), p.length, 0.9);
  EXPECT_EQ(Force(p, compressed, Vector12d::Zero()).norm(), 0.0);
  const Vector12d stretched = StraightElement(Vector3d::Zero(), Vector3d::UnitX(), p.length, 1.01);
  // Uniform strain ε: the end forces are ∓ N r' with N = EA ε.
  const double eps = 0.5 * (1.01 * 1.01 - 1.0);
  const Vector12d f = Force(p, stretched, Vector12d::Zero());
  EXPECT_NEAR(f[6], p.axial_stiffness * eps * 1.01, 1e-9 * p.axial_stiffness);
  EXPECT_NEAR(f[0], -p.axial_stiffness * eps * 1.01, 1e-9 * p.axial_stiffness);
}

TEST(AncfCable, MassMatrixIntegratesToElementMass) {
  const CableElementParameters p = MakeParameters();
  const Matrix12d m = CalcCableMassMatrix(p);
  // A uniform translation u: uᵀ M u = ρA L |u|².
  Vector12d u;
  u << 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0;
  EXPECT_NEAR(u.dot(m * u), p.mass_per_length * p.length, 1e-14);
  EXPECT_LT((m - m.transpose()).norm(), 1e-15);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix12d>(m).eigenvalues().minCoeff(), 0.0);
}

// Largest relative curvature error along an element whose nodes lie on a circle of radius R with
// tangent slopes, for an arc of `angle` radians.
double ArcCurvatureError(double angle) {
  const double radius = 0.4;
  CableElementParameters p = MakeParameters();
  p.length = radius * angle;
  Vector12d e;
  e << 0, 0, 0, 1, 0, 0, radius * std::sin(angle), radius * (1 - std::cos(angle)), 0,
      std::cos(angle), std::sin(angle), 0;
  double error = 0.0;
  for (double xi : {0.0, 0.25, 0.5, 0.75, 1.0})
    error = std::max(error, std::abs(CalcCableStrain(p, e, xi).curvature * radius - 1.0));
  return error;
}

TEST(AncfCable, CurvatureOfCircularArcConvergesQuadratically) {
  const double coarse = ArcCurvatureError(0.4);
  const double fine = ArcCurvatureError(0.2);
  EXPECT_LT(fine, 1e-2);
  EXPECT_GT(coarse / fine, 3.5);  // O(h²): halving the element divides the error by about 4
}

TEST(AncfCable, DistributedForceIntegratesShapeFunctions) {
  const CableElementParameters p = MakeParameters();
  const Vector3d w(0.0, 0.0, -9.81);
  const Vector12d q = CalcCableDistributedForce(p, w);
  // Total force equals w L; moment about node A equals w L²/2 (checked through the shape).
  EXPECT_NEAR(q[2] + q[8], -9.81 * p.length, 1e-12);
  Vector12d q_quad = Vector12d::Zero();
  for (int i = 0; i < 100; ++i) {
    const double xi = (i + 0.5) / 100.0;
    q_quad += DistributeForce(CalcHermiteShape(xi, p.length).s, w) * p.length / 100.0;
  }
  EXPECT_LT((q - q_quad).norm(), 1e-5);
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

// The axial force of each law is the derivative of its strain energy density: for a straight
// element stretched by λ, ε = (λ² − 1)/2 and U = L ψ(ε), so dU/dλ = L N(ε) λ / EA · EA.
TEST(AncfCable, AxialForceIsTheDerivativeOfTheEnergyForEveryLaw) {
  for (int law = 0; law < 3; ++law) {
    CableElementParameters p = MakeParameters();
    p.bending_stiffness = 0.0;
    p.tension_only = law > 0;
    p.rope_smoothing_strain = law == 2 ? 1e-3 : 0.0;
    for (double stretch : {0.97, 0.9995, 1.0004, 1.02}) {
      const Vector3d dir = Vector3d(1, 2, -0.5).normalized();
      const auto energy = [&](double l) {
        return CalcCableStrainEnergy(p, StraightElement(Vector3d::Zero(), dir, p.length, l));
      };
      const double h = 1e-7;
      const double du_dlambda = (energy(stretch + h) - energy(stretch - h)) / (2 * h);
      const double strain = 0.5 * (stretch * stretch - 1.0);
      const double force = CalcCableAxialForce(p, strain);
      EXPECT_NEAR(force * stretch * p.length, du_dlambda, 1e-6 * p.axial_stiffness * p.length)
          << "law " << law << ", stretch " << stretch;
    }
  }
  CableElementParameters rope = MakeParameters();
  rope.tension_only = true;
  EXPECT_EQ(CalcCableAxialForce(rope, -0.01), 0.0);  // never pushes
  EXPECT_DOUBLE_EQ(CalcCableAxialForce(rope, 0.01), 0.01 * rope.axial_stiffness);
}

}  // namespace
}  // namespace ancfnet

namespace ancfnet {
namespace {

// A stretched rope shortening faster than ε/τ carries no force: N = max(EA (ε + τ ε̇), 0) = 0.
// Its elastic part, the gradient of the strain energy that is accounted, must then be cancelled
// by the viscous part, so that Q − Q_visc = ∂U/∂e and the energy the dashpot takes is counted
// as dissipated (before issue 17 Q_visc was 0 there and the account lost EA ε ε̇ per unit length).
TEST(AncfCable, SlackeningRopeKeepsItsElasticForceInTheEnergyAccount) {
  CableElementParameters p = MakeParameters();
  p.tension_only = true;
  p.bending_stiffness = 0.0;
  p.axial_damping_time = 0.01;
  const Vector3d dir = Vector3d::UnitX();
  const Vector12d e = StraightElement(Vector3d::Zero(), dir, p.length, 1.001);
  Vector12d v = Vector12d::Zero();
  v.segment<3>(6) = -1.0 * dir;  // the far end comes back at 1 m/s: ε̇ ≈ −1/L ≪ −ε/τ
  Vector12d force, viscous;
  CalcCableInternalForce(p, e, v, {.force = &force, .viscous_force = &viscous});
  EXPECT_EQ(force.norm(), 0.0);
  for (int i = 0; i < 12; ++i) {
    Vector12d ep = e, em = e;
    ep[i] += 1e-7;
    em[i] -= 1e-7;
    const double gradient = (CalcCableStrainEnergy(p, ep) - CalcCableStrainEnergy(p, em)) / 2e-7;
    EXPECT_NEAR(force[i] - viscous[i], gradient, 1e-6 * p.axial_stiffness) << "coordinate " << i;
  }
  EXPECT_GT(viscous.norm(), 1e-4 * p.axial_stiffness);  // the elastic force it cancels
}

}  // namespace
}  // namespace ancfnet
