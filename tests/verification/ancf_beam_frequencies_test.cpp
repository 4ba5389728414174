// Natural frequencies of a simply supported ANCF beam (elements/ancf_beam.hpp) with fork
// supports against closed forms: Timoshenko bending in both planes (Timoshenko 1921; the
// pinned–pinned frequency equation, e.g. Han, Benaroya & Wei 1999, J. Sound Vib. 225:935,
// eq. 43), the axial modes of a fixed–free rod and the torsion modes of a bar fixed in twist at
// both ends (Blevins 1979, tables 8-16 and 8-19). A stocky beam (L/h = 10) so that shear and
// rotary inertia move the bending frequencies by 2–10 % from Euler–Bernoulli: the 0.3 %
// tolerance fails if either is missing (at 48 elements the errors are 2e-4 to 1.5e-3).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "beam_statics.hpp"

namespace ancfnet {
namespace {

using test::BeamDof;

constexpr double kLength = 1.0;
constexpr double kHeight = 0.1;  // along y
constexpr double kWidth = 0.06;  // along z
constexpr int kElements = 48;
const BeamMaterial kSteel{.youngs_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850.0};

enum ModeKind { kAxial = 0, kBendingY = 1, kBendingZ = 2, kTorsion = 3 };

struct Mode {
  double omega = 0.0;  // rad/s
  ModeKind kind = kAxial;
};

// Modes of the fork-supported beam: node 0 pinned, the last node on a roller along x, both
// held in twist (d₂·e_z = d₃·e_y = 0). Each mode is classed by the coordinates it moves.
std::vector<Mode> CalcModes() {
  const BeamSection section = MakeRectangleBeamSection(kHeight, kWidth, kSteel.poisson_ratio);
  test::BeamChain chain = test::MakeStraightBeamChain(kSteel, section, kLength, kElements);
  const int n = static_cast<int>(chain.q.size());
  MatrixXd k = MatrixXd::Zero(n, n), m = MatrixXd::Zero(n, n);
  const Matrix24d element_mass = CalcBeamMassMatrix(chain.element);
  for (int el = 0; el < kElements; ++el) {
    Matrix24d element_stiffness;
    const int offset = kBeamNodeDofs * el;
    CalcBeamInternalForce(chain.element, chain.q.segment<kBeamElementDofs>(offset),
                          Vector24d::Zero(), {.stiffness = &element_stiffness});
    k.block<kBeamElementDofs, kBeamElementDofs>(offset, offset) += element_stiffness;
    m.block<kBeamElementDofs, kBeamElementDofs>(offset, offset) += element_mass;
  }
  std::vector<int> fixed = {BeamDof(0, 0, 0), BeamDof(0, 0, 1), BeamDof(0, 0, 2),
                            BeamDof(kElements, 0, 1), BeamDof(kElements, 0, 2)};
  for (const int node : {0, kElements}) {
    fixed.push_back(BeamDof(node, 2, 2));
    fixed.push_back(BeamDof(node, 3, 1));
  }
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (std::find(fixed.begin(), fixed.end(), i) == fixed.end()) free.push_back(i);
  const int nf = static_cast<int>(free.size());
  MatrixXd kf(nf, nf), mf(nf, nf);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j) {
      kf(i, j) = k(free[i], free[j]);
      mf(i, j) = m(free[i], free[j]);
    }
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> eig(kf, mf);
  std::vector<Mode> modes;
  for (int i = 0; i < nf; ++i) {
    VectorXd shape = VectorXd::Zero(n);
    for (int j = 0; j < nf; ++j) shape[free[j]] = eig.eigenvectors()(j, i);
    std::array<double, 4> amount{};
    for (int node = 0; node <= kElements; ++node) {
      amount[kAxial] += std::pow(shape[BeamDof(node, 0, 0)], 2);
      amount[kBendingY] += std::pow(shape[BeamDof(node, 0, 1)], 2);
      amount[kBendingZ] += std::pow(shape[BeamDof(node, 0, 2)], 2);
      amount[kTorsion] +=
          std::pow(shape[BeamDof(node, 2, 2)], 2) + std::pow(shape[BeamDof(node, 3, 1)], 2);
    }
    const auto kind =
        static_cast<ModeKind>(std::max_element(amount.begin(), amount.end()) - amount.begin());
    modes.push_back({std::sqrt(eig.eigenvalues()[i]), kind});
  }
  return modes;
}

std::vector<double> Frequencies(const std::vector<Mode>& modes, ModeKind kind, int count) {
  std::vector<double> omega;
  for (const Mode& mode : modes)
    if (mode.kind == kind && static_cast<int>(omega.size()) < count) omega.push_back(mode.omega);
  return omega;
}

// Pinned–pinned Timoshenko beam, mode j: the smaller root x = ω² of
// ρA ρI x² − [ρA (EI k² + κGA) + ρI κGA k²] x + κGA EI k⁴ = 0, k = jπ/L.
double TimoshenkoPinnedPinned(int j, double ei, double kga, double rho_a, double rho_i) {
  const double k = j * std::numbers::pi / kLength;
  const double a = rho_a * rho_i;
  const double b = rho_a * (ei * k * k + kga) + rho_i * kga * k * k;
  const double c = kga * ei * std::pow(k, 4);
  return std::sqrt((b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a));
}

TEST(AncfBeamFrequencies, SimplySupportedBeamAgainstClosedForms) {
  const std::vector<Mode> modes = CalcModes();
  const BeamSection s = MakeRectangleBeamSection(kHeight, kWidth, kSteel.poisson_ratio);
  const double e = kSteel.youngs_modulus, rho = kSteel.density;
  const double g = e / (2.0 * (1.0 + kSteel.poisson_ratio));
  const double pi = std::numbers::pi;

  const std::vector<double> bending_y = Frequencies(modes, kBendingY, 3);
  const std::vector<double> bending_z = Frequencies(modes, kBendingZ, 3);
  ASSERT_EQ(bending_y.size(), 3u);
  ASSERT_EQ(bending_z.size(), 3u);
  for (int j = 1; j <= 3; ++j) {
    const double y =
        TimoshenkoPinnedPinned(j, e * s.second_moment_z, s.shear_correction_y * g * s.area,
                               rho * s.area, rho * s.second_moment_z);
    const double z =
        TimoshenkoPinnedPinned(j, e * s.second_moment_y, s.shear_correction_z * g * s.area,
                               rho * s.area, rho * s.second_moment_y);
    EXPECT_NEAR(bending_y[j - 1], y, 3e-3 * y) << "bending in y, mode " << j;
    EXPECT_NEAR(bending_z[j - 1], z, 3e-3 * z) << "bending in z, mode " << j;
  }
  const std::vector<double> axial = Frequencies(modes, kAxial, 2);
  const std::vector<double> torsion = Frequencies(modes, kTorsion, 2);
  ASSERT_EQ(axial.size(), 2u);
  ASSERT_EQ(torsion.size(), 2u);
  for (int j = 1; j <= 2; ++j) {
    const double rod = (2 * j - 1) * pi / (2.0 * kLength) * std::sqrt(e / rho);
    const double twist =
        j * pi / kLength *
        std::sqrt(g * s.torsion_constant / (rho * (s.second_moment_y + s.second_moment_z)));
    EXPECT_NEAR(axial[j - 1], rod, 3e-3 * rod) << "axial mode " << j;
    EXPECT_NEAR(torsion[j - 1], twist, 3e-3 * twist) << "torsion mode " << j;
  }
}

}  // namespace
}  // namespace ancfnet
