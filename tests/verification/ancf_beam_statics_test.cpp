// Statics of the ANCF beam element (elements/ancf_beam.hpp) against beam theory:
//  - the Timoshenko cantilever and its large deflection (Nachbagauer, Pechstein, Irschik &
//    Gerstmayr 2011, Multibody Syst. Dyn. 26:245, the "Cantilever" examples; the closed form
//    PL³/(3EI) + PL/(kGA) for the small load);
//  - Saint-Venant torsion of a square bar, φ = TL/(GJ) (Timoshenko & Goodier 1970, §109);
//  - the Princeton beam experiment (Dowell, Traybar & Hodges 1977), against the beam-element
//    (ANSYS BEAM188) solutions tabulated by Obrezkov, Matikainen et al. (2022), Nonlinear Dyn.
//    109:531, for the weak-direction tip displacement at load angles 0–90°.
// Each tolerance is the one the issue asks for (issue 13) and fails if the physics is wrong:
// dropping shear changes the cantilever's deflection by 4.6 %, a wrong G or J the twist by > 1 %.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "beam_statics.hpp"

namespace ancfnet {
namespace {

using test::BeamChain;
using test::BeamDof;

// L = 2 m, height 0.5 m along y (the load's direction), width 0.1 m, E = 2.07e11 Pa, ν = 0.3,
// Cowper's k = 10(1 + ν)/(12 + 11ν) = 0.849673 (Nachbagauer et al. 2011, section 5).
BeamChain MakeCantilever(int elements) {
  const BeamMaterial steel{.youngs_modulus = 2.07e11, .poisson_ratio = 0.3, .density = 7800.0};
  const BeamSection section = MakeRectangleBeamSection(0.5, 0.1, 0.3);
  EXPECT_NEAR(section.shear_correction_y, 0.849673, 1e-6);
  return test::MakeStraightBeamChain(steel, section, 2.0, elements);
}

// A dead force F e_y on the tip node.
test::BeamLoad TipForce(int tip, double force) {
  return [tip, force](const VectorXd&, double lambda, VectorXd& f,
                      std::vector<Eigen::Triplet<double>>&) {
    f[BeamDof(tip, 0, 1)] += lambda * force;
  };
}

struct TipDisplacement {
  double shortening = 0.0;
  double deflection = 0.0;
};

TipDisplacement SolveCantilever(int elements, double force, int load_steps) {
  BeamChain chain = MakeCantilever(elements);
  test::SolveBeamStatics(chain, test::ClampFirstNode(), TipForce(elements, force), load_steps);
  return {2.0 - chain.q[BeamDof(elements, 0, 0)], chain.q[BeamDof(elements, 0, 1)]};
}

TEST(AncfBeamStatics, TimoshenkoCantileverTipDeflection) {
  // PL³/(3EI) + PL/(kGA) = 7.72947e-4 + 3.69530e-5 m (Nachbagauer et al. 2011: 8.099034e-4 m).
  const TipDisplacement tip = SolveCantilever(64, 62.5e3, 1);
  EXPECT_NEAR(tip.deflection, 8.099034e-4, 1e-4 * 8.099034e-4);
}

TEST(AncfBeamStatics, LargeDeflectionOfTheTimoshenkoCantilever) {
  // Converged values of Nachbagauer et al. (2011) for P = 6.25e7 N, which are those of the
  // Simo–Reissner rod (a shooting solution of its equations agrees to 1e-6).
  const TipDisplacement tip = SolveCantilever(64, 6.25e7, 10);
  EXPECT_NEAR(tip.shortening, 0.15097103, 5e-4 * 0.15097103);
  EXPECT_NEAR(tip.deflection, 0.71056837, 5e-4 * 0.71056837);
}

// A torque T about the fixed x axis on the tip's directors, as the conservative load of the
// potential −T (φ₂ + φ₃)/2 with φ₂, φ₃ the angles of d₂ and d₃ about x:
// Q_d = (T/2) (e_x × d)/|d_⊥|² for d = d₂, d₃.
test::BeamLoad TipTorque(int tip, double torque) {
  return [tip, torque](const VectorXd& q, double lambda, VectorXd& f,
                       std::vector<Eigen::Triplet<double>>& jacobian) {
    for (const int block : {2, 3}) {
      const int i = BeamDof(tip, block, 0);
      const double dy = q[i + 1], dz = q[i + 2];
      const double s = dy * dy + dz * dz;
      const double t = 0.5 * lambda * torque;
      f[i + 1] += -t * dz / s;
      f[i + 2] += t * dy / s;
      // ∂Q/∂d on the (y, z) components.
      jacobian.emplace_back(i + 1, i + 1, t * 2.0 * dy * dz / (s * s));
      jacobian.emplace_back(i + 1, i + 2, -t / s + t * 2.0 * dz * dz / (s * s));
      jacobian.emplace_back(i + 2, i + 1, t / s - t * 2.0 * dy * dy / (s * s));
      jacobian.emplace_back(i + 2, i + 2, -t * 2.0 * dy * dz / (s * s));
    }
  };
}

TEST(AncfBeamStatics, SaintVenantTorsionOfASquareBar) {
  // L = 1 m, a = 0.01 m, E = 71.7e9 Pa, ν = 0.33, T = 10 N m: φ = TL/(GJ) with
  // J = 0.1406 a⁴ gives 0.263815 rad (issue 13); the exact J = 0.140577 a⁴ gives 0.263905 rad.
  const BeamMaterial aluminium{.youngs_modulus = 71.7e9, .poisson_ratio = 0.33, .density = 2700.0};
  const BeamSection section = MakeRectangleBeamSection(0.01, 0.01, 0.33);
  const int elements = 8;
  BeamChain chain = test::MakeStraightBeamChain(aluminium, section, 1.0, elements);
  test::SolveBeamStatics(chain, test::ClampFirstNode(), TipTorque(elements, 10.0), 2);
  const double twist =
      std::atan2(chain.q[BeamDof(elements, 2, 2)], chain.q[BeamDof(elements, 2, 1)]);
  EXPECT_NEAR(twist, 0.263815, 0.01 * 0.263815);
  const double g = 71.7e9 / (2.0 * 1.33);
  EXPECT_NEAR(twist, 10.0 / (g * section.torsion_constant), 1e-3 * twist);
  // The axis neither moves nor bends.
  EXPECT_LT((chain.q.segment<3>(BeamDof(elements, 0, 0)) - Vector3d::UnitX()).norm(), 1e-8);
}

TEST(AncfBeamStatics, PrincetonBeamWeakDirectionTipDisplacement) {
  // L = 0.508 m, 12.3777 × 3.2024 mm (height along y), E = 71.7e9 Pa, ν = 0.31, clamped; a dead
  // tip force F (−cos β e_y + sin β e_z); β = 0, 15, …, 90°. The 32-element solution is within
  // 0.18 % of the reference at every angle; the issue asks for 1 %.
  struct Case {
    double force;
    std::array<double, 7> weak;  // tip displacement along z (m), β = 0, 15, …, 90°
  };
  const std::array<Case, 2> cases{
      Case{8.896, {0.0, 4.208232e-2, 7.939483e-2, 0.1089879, 0.1298876, 0.1421944, 0.1462460}},
      Case{13.345, {0.0, 6.435813e-2, 0.1177360, 0.1564672, 0.1818616, 0.1960971, 0.2006777}}};
  const BeamMaterial aluminium{.youngs_modulus = 71.7e9, .poisson_ratio = 0.31, .density = 2700.0};
  const BeamSection section = MakeRectangleBeamSection(12.3777e-3, 3.2024e-3, 0.31);
  const int elements = 32;
  for (const Case& c : cases)
    for (int i = 1; i < 7; ++i) {
      const double beta = i * 15.0 * std::numbers::pi / 180.0;
      BeamChain chain = test::MakeStraightBeamChain(aluminium, section, 0.508, elements);
      const double fy = -c.force * std::cos(beta), fz = c.force * std::sin(beta);
      test::SolveBeamStatics(
          chain, test::ClampFirstNode(),
          [&](const VectorXd&, double lambda, VectorXd& f, std::vector<Eigen::Triplet<double>>&) {
            f[BeamDof(elements, 0, 1)] += lambda * fy;
            f[BeamDof(elements, 0, 2)] += lambda * fz;
          },
          10);
      EXPECT_NEAR(chain.q[BeamDof(elements, 0, 2)], c.weak[i], 0.01 * c.weak[i])
          << "F = " << c.force << " N, beta = " << 15 * i << " deg";
    }
}

}  // namespace
}  // namespace ancfnet
