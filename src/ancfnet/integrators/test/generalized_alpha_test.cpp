// Generalised-α on a single linear oscillator (a point mass on a linear spring along its axis)
// against the method's amplification matrix (Chung & Hulbert 1993): its spectral radius is 1 as
// ωh → 0 and ρ∞ as ωh → ∞, the trapezoidal rule (ρ∞ = 1) keeps the amplitude and turns by
// 2 atan(ωh/2) per step, and the integrator's displacements are the powers of that matrix.

#include "ancfnet/integrators/generalized_alpha.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <vector>

#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kMass = 2.0;         // kg
constexpr double kStiffness = 800.0;  // N/m: ω = 20 rad/s
constexpr double kLength = 100.0;     // natural length of the spring (m)
constexpr double kAmplitude = 0.1;    // initial stretch (m)

// The oscillator: an anchor fixed at the origin, the mass at x = L + A at rest, both on the x
// axis, so the motion stays on it and the spring force −k (x − L) is linear in x. The spring is
// long so that no Newton iterate takes the mass past the anchor, where the force is not linear.
Model MakeOscillator() {
  ModelBuilder builder;
  builder.AddPointMass("anchor", 1.0, Vector3d::Zero());
  builder.FixPointMass("anchor");
  builder.AddPointMass("mass", kMass, Vector3d(kLength + kAmplitude, 0.0, 0.0));
  builder.AddSpringDamper("spring", {"anchor"}, {"mass"}, MakeLinearLaw(kStiffness), kLength);
  return builder.Build();
}

// Displacements x_n − L of the oscillator integrated with steps of h = ωh/ω, n = 0 … steps.
std::vector<double> IntegrateOscillator(double rho_infinity, double omega_h, int steps) {
  const Model model = MakeOscillator();
  const double h = omega_h / std::sqrt(kStiffness / kMass);
  DynamicSettings settings;
  settings.spectral_radius = rho_infinity;
  settings.time_step = h;
  GeneralizedAlphaIntegrator integrator(model, settings);
  State state = MakeInitialState(model);
  EXPECT_TRUE(integrator.Initialize(&state));
  const Index x = model.point_masses()[1].dof;
  std::vector<double> displacements{state.q[x] - kLength};
  for (int n = 0; n < steps; ++n) {
    const StepOutcome outcome = integrator.Step(h, &state);
    EXPECT_TRUE(outcome.accepted) << outcome.failure;
    displacements.push_back(state.q[x] - kLength);
  }
  return displacements;
}

// Chung & Hulbert (1993) for ẍ + ω² x = 0 in the variables (x, h v, h² a) of a step
// of size h (Ω = ωh):
//   (1 − α_m) a_{n+1} + α_m a_n + Ω²/h² ((1 − α_f) x_{n+1} + α_f x_n) = 0,
//   x_{n+1} = x_n + h v_n + h² ((½ − β) a_n + β a_{n+1}),
//   v_{n+1} = v_n + h ((1 − γ) a_n + γ a_{n+1}),
// solved for step n + 1: (x, h v, h² a)_{n+1} = A (x, h v, h² a)_n.
Matrix3d CalcAmplificationMatrix(const GeneralizedAlphaCoefficients& c, double omega_h) {
  const double w2 = omega_h * omega_h;
  Matrix3d a;
  for (int j = 0; j < 3; ++j) {
    const Vector3d y = Vector3d::Unit(j);  // (x, h v, h² a)_n
    const double a_next =
        -(c.alpha_m * y[2] + w2 * (y[0] + (1.0 - c.alpha_f) * (y[1] + (0.5 - c.beta) * y[2]))) /
        ((1.0 - c.alpha_m) + w2 * c.beta * (1.0 - c.alpha_f));
    a(0, j) = y[0] + y[1] + (0.5 - c.beta) * y[2] + c.beta * a_next;
    a(1, j) = y[1] + (1.0 - c.gamma) * y[2] + c.gamma * a_next;
    a(2, j) = a_next;
  }
  return a;
}

Eigen::Vector3cd CalcRoots(const Matrix3d& a) {
  return Eigen::EigenSolver<Matrix3d>(a, false).eigenvalues();
}

// ρ(A): the largest modulus of its eigenvalues.
double CalcSpectralRadius(const Matrix3d& a) { return CalcRoots(a).cwiseAbs().maxCoeff(); }

// The principal root of a resolved vibration, ρ e^{iΩ̄}: the eigenvalue with the largest
// imaginary part (the third, spurious root is real).
std::complex<double> CalcPrincipalRoot(const Matrix3d& a) {
  const Eigen::Vector3cd roots = CalcRoots(a);
  Eigen::Index principal = 0;
  roots.imag().maxCoeff(&principal);
  return roots[principal];
}

TEST(GeneralizedAlphaTest, CoefficientsAreSecondOrderAndUnconditionallyStable) {
  // Chung & Hulbert (1993): second-order accuracy and the optimal high-frequency dissipation.
  for (double rho : {0.0, 0.3, 0.5, 0.8, 1.0}) {
    const auto c = GeneralizedAlphaCoefficients::FromSpectralRadius(rho);
    EXPECT_NEAR(c.gamma, 0.5 - c.alpha_m + c.alpha_f, 1e-15) << "ρ∞ = " << rho;
    EXPECT_NEAR(c.beta, 0.25 * std::pow(1.0 - c.alpha_m + c.alpha_f, 2), 1e-15) << "ρ∞ = " << rho;
    EXPECT_LE(c.alpha_m, c.alpha_f);
    EXPECT_LE(c.alpha_f, 0.5);
  }
}

TEST(GeneralizedAlphaTest, SpectralRadiusIsOneAtLowAndRhoInfinityAtHighFrequency) {
  for (double rho : {0.0, 0.3, 0.5, 0.8, 1.0}) {
    const auto c = GeneralizedAlphaCoefficients::FromSpectralRadius(rho);
    EXPECT_NEAR(CalcSpectralRadius(CalcAmplificationMatrix(c, 1e-3)), 1.0, 1e-9) << "ρ∞ = " << rho;
    EXPECT_NEAR(CalcSpectralRadius(CalcAmplificationMatrix(c, 1e8)), rho, 1e-4) << "ρ∞ = " << rho;
    // Never above 1 in between (unconditional stability), and decreasing towards ρ∞. (Beyond
    // ωh ≈ 100 the three roots close in on −ρ∞, a triple root, and their rounding grows to ~10⁻⁶.)
    double previous = 1.0;
    for (double omega_h = 0.1; omega_h < 100.0; omega_h *= 1.2) {
      const double radius = CalcSpectralRadius(CalcAmplificationMatrix(c, omega_h));
      EXPECT_LE(radius, previous * (1.0 + 1e-9)) << "ρ∞ = " << rho << ", ωh = " << omega_h;
      previous = radius;
    }
  }
}

TEST(GeneralizedAlphaTest, TrapezoidalRuleKeepsTheAmplitudeAndLengthensThePeriod) {
  // ρ∞ = 1: x_n = A cos(n Ω̄) exactly, with Ω̄ = 2 atan(Ω/2) the discrete frequency per step
  // (the period grows by Ω/Ω̄ ≈ 1 + Ω²/12).
  const double omega_h = 0.5;
  const std::vector<double> x = IntegrateOscillator(1.0, omega_h, 200);
  const double omega_bar = 2.0 * std::atan(0.5 * omega_h);
  EXPECT_NEAR(std::arg(CalcPrincipalRoot(CalcAmplificationMatrix(
                  GeneralizedAlphaCoefficients::FromSpectralRadius(1.0), omega_h))),
              omega_bar, 1e-12);
  for (std::size_t n = 0; n < x.size(); ++n)
    ASSERT_NEAR(x[n], kAmplitude * std::cos(static_cast<double>(n) * omega_bar), 1e-11 * kAmplitude)
        << "step " << n;
}

TEST(GeneralizedAlphaTest, DisplacementsFollowTheAmplificationMatrix) {
  // Resolved (ωh = 0.5) and unresolved (ωh = 5) vibration with numerical damping: every step
  // must be the matrix's, so the decay is the one its spectral radius sets.
  for (double rho : {0.0, 0.5, 0.8}) {
    for (double omega_h : {0.5, 5.0}) {
      const int steps = 100;
      const std::vector<double> x = IntegrateOscillator(rho, omega_h, steps);
      const Matrix3d a =
          CalcAmplificationMatrix(GeneralizedAlphaCoefficients::FromSpectralRadius(rho), omega_h);
      Vector3d y(kAmplitude, 0.0, -omega_h * omega_h * kAmplitude);  // consistent a₀ = −ω² x₀
      for (int n = 0; n <= steps; ++n) {
        ASSERT_NEAR(x[n], y[0], 1e-10 * kAmplitude)
            << "ρ∞ = " << rho << ", ωh = " << omega_h << ", step " << n;
        y = a * y;
      }
    }
  }
}

}  // namespace
}  // namespace ancfnet
