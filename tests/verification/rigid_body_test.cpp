// Rigid bodies through the dynamic solvers: the torque-free symmetric top against its closed
// form (and the observed order of convergence), the Dzhanibekov flip against the elliptic-function
// period (Landau & Lifshitz, Mechanics, §37), free fall with constant spin, a prescribed body,
// and attachments: a pendulum hung from a fixed body and a point mass tied to a spinning free
// body (momentum and energy).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "ancfnet/analysis/momentum.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/solvers/static_solver.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {
namespace {

DynamicSettings Settings(IntegratorType integrator, double rho, double h, double end_time) {
  DynamicSettings s;
  s.integrator = integrator;
  s.spectral_radius = rho;
  s.time_step = h;
  s.end_time = end_time;
  s.newton.relative_tolerance = 1e-12;
  s.newton.absolute_tolerance = 1e-13;
  s.newton.max_iterations = 20;
  return s;
}

Model OneBody(const Vector3d& inertia, const Vector3d& w_B, const Vector3d& gravity = {0, 0, 0},
              const Vector3d& velocity = Vector3d::Zero(), BodyMotion motion = BodyMotion::kFree) {
  ModelBuilder builder;
  builder.SetGravity(gravity);
  builder.AddRigidBody(
      {.name = "body",
       .mass = 3.0,
       .inertia = inertia.asDiagonal(),
       .position = Vector3d(0.5, -1.0, 2.0),
       .orientation = Matrix3d(Eigen::AngleAxisd(0.4, Vector3d(1, 1, 0).normalized())),
       .velocity = velocity,
       .angular_velocity = w_B,
       .motion = motion});
  return builder.Build();
}

// Runs and calls `sample` with every output state.
SolveResult Simulate(const Model& model, const DynamicSettings& settings,
                     const std::function<void(const State&, const EnergyAccount&)>& sample,
                     State* final_state = nullptr) {
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(model, settings, 0.0, sample, &state);
  EXPECT_TRUE(result.completed) << result.message;
  if (final_state) *final_state = state;
  return result;
}

// ---------------------------------------------------------------------------------------------
// Torque-free symmetric top J = diag(J₁, J₁, J₃): ω₁ = a cos Ωt, ω₂ = a sin Ωt, ω₃ constant,
// Ω = (J₃ − J₁)/J₁ ω₃ (body frame).

constexpr double kJ1 = 1.0, kJ3 = 2.0, kSpin = 10.0, kWobble = 1.0;

double TopError(IntegratorType integrator, double rho, double h, double end_time) {
  const Model model = OneBody(Vector3d(kJ1, kJ1, kJ3), Vector3d(kWobble, 0.0, kSpin));
  const double rate = (kJ3 - kJ1) / kJ1 * kSpin;
  double error = 0.0;
  Simulate(
      model, Settings(integrator, rho, h, end_time), [&](const State& s, const EnergyAccount&) {
        const Vector3d exact(kWobble * std::cos(rate * s.t), kWobble * std::sin(rate * s.t), kSpin);
        error = std::max(error, (s.v.segment<3>(3) - exact).norm());
      });
  return error;
}

TEST(RigidBody, SymmetricTopPrecessesAtTheAnalyticRateWithSecondOrder) {
  const double period = 2.0 * std::numbers::pi / ((kJ3 - kJ1) / kJ1 * kSpin);
  const double end = 3.0 * period;
  struct Case {
    IntegratorType integrator;
    double rho;
    const char* name;
  };
  for (const Case& c : {Case{IntegratorType::kGeneralizedAlpha, 0.8, "gen-alpha 0.8"},
                        Case{IntegratorType::kGeneralizedAlpha, 1.0, "gen-alpha 1.0"},
                        Case{IntegratorType::kImplicitMidpoint, 1.0, "midpoint"}}) {
    const double coarse = TopError(c.integrator, c.rho, period / 400.0, end);
    const double fine = TopError(c.integrator, c.rho, period / 800.0, end);
    const double finest = TopError(c.integrator, c.rho, period / 3200.0, end);
    const double order = std::log2(coarse / fine);
    std::printf(
        "%s: max |ω − ω_exact| over 3 periods %.3e (h = T/400), %.3e (T/800), %.3e "
        "(T/3200); order %.3f\n",
        c.name, coarse, fine, finest, order);
    EXPECT_NEAR(order, 2.0, 0.1) << c.name;
    EXPECT_LT(finest, 1e-4) << c.name;
  }
}

// ---------------------------------------------------------------------------------------------
// Dzhanibekov: J = diag(1, 2, 3), spin near the intermediate axis. With M² > 2E J₂ the period of
// ω is T = 4 K(k) √(J₁J₂J₃ / ((J₃ − J₂)(M² − 2E J₁))), k² = (J₂ − J₁)(2E J₃ − M²) /
// ((J₃ − J₂)(M² − 2E J₁)) (Landau & Lifshitz §37); ω₂ changes sign twice a period (the flips).

struct FlipRun {
  double period = 0.0;          // from the upward zero crossings of ω₂
  double energy_drift = 0.0;    // max |E − E₀| / E₀
  double momentum_drift = 0.0;  // max |π − π₀| / |π₀|, π = R J ω (world)
  double norm_drift = 0.0;      // max ||π| − |π₀|| / |π₀|
};

FlipRun RunFlip(IntegratorType integrator, double rho, double h) {
  const Vector3d j(1.0, 2.0, 3.0);
  const Vector3d w0(0.0, 2.0, 0.1);
  const Model model = OneBody(j, w0);
  const double two_e = j.dot(w0.cwiseProduct(w0));
  const double m2 = j.cwiseProduct(w0).squaredNorm();
  const double k2 = (j[1] - j[0]) * (two_e * j[2] - m2) / ((j[2] - j[1]) * (m2 - two_e * j[0]));
  const double exact = 4.0 * std::comp_ellint_1(std::sqrt(k2)) *
                       std::sqrt(j.prod() / ((j[2] - j[1]) * (m2 - two_e * j[0])));
  FlipRun run;
  std::vector<double> crossings;
  double previous_w2 = w0[1], previous_t = 0.0;
  Vector3d pi0 = Vector3d::Zero();
  double e0 = 0.0;
  bool first = true;
  DynamicSettings settings = Settings(integrator, rho, h, 2.3 * exact);
  // Full Newton to round-off: the midpoint rule's invariants hold to the Newton tolerance.
  settings.jacobian_update = JacobianUpdate::kEveryIteration;
  settings.newton.relative_tolerance = 1e-14;
  settings.newton.absolute_tolerance = 1e-15;
  Simulate(model, settings, [&](const State& s, const EnergyAccount& e) {
    const Vector3d w = s.v.segment<3>(3);
    const Vector3d pi = CalcBodyPose(model, s, 0).R_WB * j.cwiseProduct(w);
    if (first) {
      pi0 = pi;
      e0 = e.kinetic;
      first = false;
    }
    run.energy_drift = std::max(run.energy_drift, std::abs(e.kinetic - e0) / e0);
    run.momentum_drift = std::max(run.momentum_drift, (pi - pi0).norm() / pi0.norm());
    run.norm_drift = std::max(run.norm_drift, std::abs(pi.norm() - pi0.norm()) / pi0.norm());
    if (previous_w2 < 0.0 && w[1] >= 0.0)
      crossings.push_back(previous_t + (s.t - previous_t) * previous_w2 / (previous_w2 - w[1]));
    previous_w2 = w[1];
    previous_t = s.t;
  });
  EXPECT_GE(crossings.size(), 2u);
  if (crossings.size() >= 2) run.period = crossings[1] - crossings[0];
  std::printf("flip period %.6f s, elliptic formula %.6f s (%.2e relative)\n", run.period, exact,
              run.period / exact - 1.0);
  EXPECT_NEAR(run.period / exact, 1.0, 0.01);
  return run;
}

TEST(RigidBody, DzhanibekovFlipMidpointConservesEnergyAndMomentumNorm) {
  const FlipRun run = RunFlip(IntegratorType::kImplicitMidpoint, 1.0, 2e-3);
  std::printf("midpoint: energy drift %.2e, |π| drift %.2e, world π drift %.2e\n", run.energy_drift,
              run.norm_drift, run.momentum_drift);
  EXPECT_LT(run.energy_drift, 1e-12);
  EXPECT_LT(run.norm_drift, 1e-12);
  EXPECT_LT(run.momentum_drift, 1e-3);
}

TEST(RigidBody, DzhanibekovFlipGeneralizedAlphaDriftsLittle) {
  const FlipRun run = RunFlip(IntegratorType::kGeneralizedAlpha, 1.0, 2e-3);
  std::printf("gen-alpha rho 1: energy drift %.2e, |π| drift %.2e, world π drift %.2e\n",
              run.energy_drift, run.norm_drift, run.momentum_drift);
  EXPECT_LT(run.energy_drift, 1e-4);
  EXPECT_LT(run.momentum_drift, 1e-3);
}

// ---------------------------------------------------------------------------------------------

TEST(RigidBody, FreeFallWithConstantSpinIsExact) {
  const Vector3d g(0.0, 0.0, -9.81), v0(1.0, 0.5, 3.0), w(0.0, 0.0, 4.0);
  for (IntegratorType integrator :
       {IntegratorType::kGeneralizedAlpha, IntegratorType::kImplicitMidpoint,
        IntegratorType::kExplicitVerlet}) {
    const Model model = OneBody(Vector3d(1.0, 1.5, 2.0), w, g, v0);
    const double balance0 =
        0.5 * 3.0 * v0.squaredNorm() + 0.5 * 2.0 * 16.0 - 3.0 * g.dot(Vector3d(0.5, -1.0, 2.0));
    double balance_error = 0.0;
    State state;
    Simulate(
        model, Settings(integrator, 0.8, 1e-2, 1.0),
        [&](const State&, const EnergyAccount& e) {
          balance_error = std::max(balance_error, std::abs(e.kinetic + e.gravity - balance0));
        },
        &state);
    const Vector3d x_exact = Vector3d(0.5, -1.0, 2.0) + v0 + 0.5 * g;
    const Matrix3d r_exact = model.rigid_bodies()[0].initial_orientation * ExpRotation(w * 1.0);
    EXPECT_LT((state.q.head<3>() - x_exact).norm(), 1e-10);
    EXPECT_LT((CalcBodyPose(model, state, 0).R_WB - r_exact).norm(), 1e-12);
    EXPECT_LT((state.v.tail<3>() - w).norm(), 1e-12);
    EXPECT_LT(balance_error, 1e-9 * balance0);
  }
}

TEST(RigidBody, PrescribedBodyFollowsItsPath) {
  const Vector3d v(0.2, -0.1, 0.3), w(0.5, 1.0, -0.7);
  // With a free point mass tied to it by a spring (the moving body carries it along).
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -9.81));
  builder.AddRigidBody(
      {.name = "body",
       .mass = 3.0,
       .inertia = Vector3d(1.0, 1.5, 2.0).asDiagonal(),
       .position = Vector3d(0.5, -1.0, 2.0),
       .orientation = Matrix3d(Eigen::AngleAxisd(0.4, Vector3d(1, 1, 0).normalized())),
       .velocity = v,
       .angular_velocity = w,
       .motion = BodyMotion::kPrescribed});
  builder.AddPointMass("m", 0.5, Vector3d(1.0, -1.0, 2.0));
  builder.AddBodyAttachment({.name = "a", .body = "body", .point = {"m"}, .stiffness = 50.0});
  const Model model = builder.Build();
  double error = 0.0;
  const Matrix3d r0 = model.rigid_bodies()[0].initial_orientation;
  Simulate(model, Settings(IntegratorType::kGeneralizedAlpha, 0.8, 1e-2, 2.0),
           [&](const State& s, const EnergyAccount&) {
             const BodyPose pose = CalcBodyPose(model, s, 0);
             error = std::max({error, (pose.p_WB - (Vector3d(0.5, -1.0, 2.0) + s.t * v)).norm(),
                               (pose.R_WB - r0 * ExpRotation(s.t * w)).norm(),
                               (s.v.segment<3>(3) - w).norm()});
           });
  EXPECT_LT(error, 1e-12);
}

// A point mass hanging statically from a point of a fixed, turned body on a spring k: it sits
// m g / k below the body point, y = x + R s_B.
TEST(RigidBody, StaticMassHangsFromAFixedBodyPoint) {
  const double mass = 2.0, k = 500.0, g = 9.81;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -g));
  const Matrix3d r = Matrix3d(Eigen::AngleAxisd(1.2, Vector3d(1.0, -0.5, 0.3).normalized()));
  const Vector3d x(1.0, 2.0, 3.0), s_B(0.2, 0.4, -0.3);
  builder.AddRigidBody({.name = "hub",
                        .mass = 50.0,
                        .inertia = Matrix3d::Identity(),
                        .position = x,
                        .orientation = r,
                        .motion = BodyMotion::kFixed});
  builder.AddPointMass("m", mass, x + r * s_B);
  builder.AddBodyAttachment(
      {.name = "spring", .body = "hub", .point = {"m"}, .body_point = s_B, .stiffness = k});
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  const SolveResult result = SolveStatic(
      model, {}, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  const Vector3d expected = x + r * s_B - Vector3d(0.0, 0.0, mass * g / k);
  EXPECT_LT((state.q.segment<3>(model.point_masses()[0].dof) - expected).norm(), 1e-10);
}

// ---------------------------------------------------------------------------------------------
// A pendulum hung from a fixed, turned body: a light stiff cord (4 elements, ρA = 0.01 kg/m)
// carrying a 1 kg bob, its top tied to the body point by a default (penalty) attachment. Small
// amplitude θ₀ = 0.05: T = 2π √(I / (g (m L + m_c L/2))) (1 + θ₀²/16), I = m L² + m_c L²/3.

TEST(RigidBody, PendulumFromAFixedBodyPointSwingsAtThePendulumPeriod) {
  const double length = 1.0, theta0 = 0.05, g = 9.81, bob = 1.0, rho_a = 0.01, h = 1e-3;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -g));
  const Matrix3d r = Matrix3d(Eigen::AngleAxisd(0.9, Vector3d(0.2, 1.0, 0.3).normalized()));
  const Vector3d hub(0.3, 0.0, 1.0), s_B(0.1, -0.2, 0.05);
  builder.AddRigidBody({.name = "hub",
                        .mass = 100.0,
                        .inertia = Vector3d(5.0, 6.0, 7.0).asDiagonal(),
                        .position = hub,
                        .orientation = r,
                        .motion = BodyMotion::kFixed});
  const Vector3d top = hub + r * s_B;
  const Vector3d end = top + length * Vector3d(std::sin(theta0), 0.0, -std::cos(theta0));
  builder.AddPointMass("bob", bob, end);
  CableProperties cord{.axial_stiffness = 1e6, .bending_stiffness = 1e-4, .mass_per_length = rho_a};
  builder.AddCable({.name = "cord",
                    .start = top,
                    .end = end,
                    .num_elements = 4,
                    .properties = cord,
                    .end_knot = "bob"});
  builder.AddBodyAttachment(
      {.name = "hook", .body = "hub", .point = {"cord", 0.0}, .body_point = s_B, .time_step = h});
  const Model model = builder.Build();
  const double m_c = rho_a * length;
  const double inertia = bob * length * length + m_c * length * length / 3.0;
  const double exact = 2.0 * std::numbers::pi *
                       std::sqrt(inertia / (g * (bob * length + 0.5 * m_c * length))) *
                       (1.0 + theta0 * theta0 / 16.0);
  std::vector<double> crossings;
  double previous_x = end.x() - top.x(), previous_t = 0.0;
  const Index bob_dof = model.point_masses()[0].dof;
  Simulate(model, Settings(IntegratorType::kGeneralizedAlpha, 0.8, h, 2.2 * exact),
           [&](const State& s, const EnergyAccount&) {
             const double x = s.q[bob_dof] - top.x();
             if (previous_x > 0.0 && x <= 0.0)
               crossings.push_back(previous_t + (s.t - previous_t) * previous_x / (previous_x - x));
             previous_x = x;
             previous_t = s.t;
           });
  ASSERT_GE(crossings.size(), 2u);
  const double period = crossings[1] - crossings[0];
  std::printf("pendulum from a body point: period %.6f s, exact %.6f s (%.2e relative)\n", period,
              exact, period / exact - 1.0);
  EXPECT_NEAR(period / exact, 1.0, 5e-3);
}

// A 2 kg point mass tied by a spring (k = 400 N/m, c = 0) to an off-centre point of a spinning
// 5 kg free body, no gravity: the pair's linear momentum is conserved and the account (kinetic +
// attachment energy) holds while energy moves between them.

// With c = 3 N s/m the attachment's damping also turns the body (its moment on ψ): the
// dissipated energy, counted with the rotation increments h ω_{n+½}, closes the balance.
void ExpectTiedPairConserves(double damping) {
  ModelBuilder builder;
  builder.AddRigidBody({.name = "chaser",
                        .mass = 5.0,
                        .inertia = Vector3d(0.4, 0.6, 0.7).asDiagonal(),
                        .position = Vector3d::Zero(),
                        .velocity = Vector3d(0.1, 0.0, 0.0),
                        .angular_velocity = Vector3d(0.3, -0.5, 2.0)});
  builder.AddPointMass("probe", 2.0, Vector3d(0.7, 0.1, 0.0), Vector3d(0.0, 0.4, -0.2));
  builder.AddBodyAttachment({.name = "tether",
                             .body = "chaser",
                             .point = {"probe"},
                             .body_point = Vector3d(0.5, 0.0, 0.0),
                             .stiffness = 400.0,
                             .damping = damping});
  const Model model = builder.Build();
  for (IntegratorType integrator :
       {IntegratorType::kImplicitMidpoint, IntegratorType::kGeneralizedAlpha}) {
    Vector3d p0 = Vector3d::Zero();
    double momentum_error = 0.0, balance0 = 0.0, balance_error = 0.0, strain_max = 0.0;
    double dissipated = 0.0;
    bool first = true;
    State state = MakeInitialState(model);
    Workspace ws(model);
    const SolveResult result = SolveDynamic(
        model, Settings(integrator, 1.0, 1e-3, 3.0), 0.0,
        [&](const State& s, const EnergyAccount& e) {
          const Vector3d p = CalcLinearMomentum(model, ws, s.v);
          if (first) {
            p0 = p;
            balance0 = e.Balance();
            first = false;
          }
          momentum_error = std::max(momentum_error, (p - p0).norm());
          balance_error = std::max(balance_error, std::abs(e.Balance() - balance0));
          strain_max = std::max(strain_max, e.strain);
          dissipated = e.dissipated;
        },
        &state);
    ASSERT_TRUE(result.completed) << result.message;
    std::printf(
        "tied pair, c = %g (%s): momentum error %.2e kg m/s, balance drift %.2e J of %.4f J "
        "(attachment energy up to %.4f J, dissipated %.4f J)\n",
        damping, integrator == IntegratorType::kImplicitMidpoint ? "midpoint" : "gen-alpha 1",
        momentum_error, balance_error, balance0, strain_max, dissipated);
    EXPECT_LT(momentum_error, 1e-10 * p0.norm() + 1e-12);
    EXPECT_GT(strain_max, 0.05 * balance0);
    EXPECT_LT(balance_error, 1e-4 * balance0);
    if (damping > 0.0) {
      EXPECT_GT(dissipated, 0.2 * balance0);
    }
  }
}

TEST(RigidBody, PointMassTiedToAFreeBodyConservesMomentumAndEnergy) {
  ExpectTiedPairConserves(0.0);
}

TEST(RigidBody, DampedTieClosesTheBalanceWithItsDissipation) { ExpectTiedPairConserves(3.0); }

}  // namespace
}  // namespace ancfnet
