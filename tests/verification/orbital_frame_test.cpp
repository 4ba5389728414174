// Clohessy–Wiltshire relative motion in the Hill frame of a target on a circular orbit: a free
// point mass follows the analytical solution over one orbit, and a free cable keeps the Jacobi
// integral (kinetic + strain + tidal potential) constant.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ancfnet/common/skew.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {
namespace {

constexpr double kMeanMotion = 0.0011;  // rad/s, a low Earth orbit (period about 95 min)

// Clohessy & Wiltshire (1960): x radial, y along-track, z orbit normal.
Vector3d AnalyticalPosition(const Vector3d& r0, const Vector3d& v0, double t) {
  const double n = kMeanMotion, c = std::cos(n * t), s = std::sin(n * t);
  return {(4.0 - 3.0 * c) * r0.x() + s / n * v0.x() + 2.0 / n * (1.0 - c) * v0.y(),
          6.0 * (s - n * t) * r0.x() + r0.y() - 2.0 / n * (1.0 - c) * v0.x() +
              (4.0 * s - 3.0 * n * t) / n * v0.y(),
          c * r0.z() + s / n * v0.z()};
}

DynamicSettings OneOrbit(double steps_per_orbit) {
  DynamicSettings settings;
  const double period = 2.0 * std::numbers::pi / kMeanMotion;
  settings.spectral_radius = 1.0;
  settings.time_step = period / steps_per_orbit;
  settings.end_time = period;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-12;
  return settings;
}

// The largest change of the Jacobi integral kinetic + strain + gravity (the tidal potential is in
// the gravity column) over a run, and the largest kinetic energy; a run that does not complete
// fails the test.
struct JacobiDrift {
  double worst = 0.0;
  double kinetic = 0.0;
};

JacobiDrift RunForJacobiDrift(const Model& model, const DynamicSettings& settings) {
  State state = MakeInitialState(model);
  JacobiDrift drift;
  double first = 0.0;
  bool started = false;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State&, const EnergyAccount& e) {
        const double jacobi = e.kinetic + e.strain + e.gravity;
        if (!started) first = jacobi;
        started = true;
        drift.worst = std::max(drift.worst, std::abs(jacobi - first));
        drift.kinetic = std::max(drift.kinetic, e.kinetic);
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  return drift;
}

TEST(OrbitalFrame, FreePointMassFollowsClohessyWiltshireOverOneOrbit) {
  const Vector3d r0(10.0, -5.0, 3.0), v0(0.01, -0.02, 0.005);
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddPointMass("chaser", 2.0, r0, v0);
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  double worst = 0.0, scale = 0.0;
  const SolveResult result = SolveDynamic(
      model, OneOrbit(20000), 0.0,
      [&](const State& s, const EnergyAccount&) {
        const Vector3d exact = AnalyticalPosition(r0, v0, s.t);
        worst = std::max(worst, (s.q.segment<3>(0) - exact).norm());
        scale = std::max(scale, exact.norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_LT(worst, 1e-6 * scale);  // trapezoidal rule: phase error about (n h)² n t / 12
}

TEST(OrbitalFrame, FreeCableKeepsTheJacobiIntegral) {
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddCable({.name = "tether",
                    .start = Vector3d(5.0, 0.0, 0.0),
                    .end = Vector3d(25.0, 0.0, 0.0),
                    .num_elements = 4,
                    .properties = MakeCableProperties({.youngs_modulus = 1e9, .density = 1400},
                                                      MakeCircleSection(0.002))});
  builder.SetInitialVelocity("tether", Vector3d(0.0, 0.01, 0.0), Vector3d(0, 0, 0.002),
                             Vector3d(15.0, 0.0, 0.0));
  const Model model = builder.Build();
  DynamicSettings settings = OneOrbit(2000);
  settings.end_time /= 4.0;
  const JacobiDrift drift = RunForJacobiDrift(model, settings);
  EXPECT_LT(drift.worst, 1e-6 * drift.kinetic);
}

// A free rigid body (examples: a tumbling target, issue 16): its centre of mass follows the
// Clohessy–Wiltshire solution whatever its tumble, since the frame's forces on it act through the
// centre of mass (forces/orbital_frame_body.hpp).
TEST(OrbitalFrame, TumblingBodyCentreFollowsClohessyWiltshire) {
  const Vector3d r0(-8.0, 4.0, -2.0), v0(-0.005, 0.015, 0.01);
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddRigidBody({.name = "target",
                        .mass = 500.0,
                        .inertia = Vector3d(300.0, 400.0, 450.0).asDiagonal(),
                        .position = r0,
                        .velocity = v0,
                        .angular_velocity = Vector3d(0.005, 0.1, 0.005)});
  const Model model = builder.Build();
  const Index x = model.rigid_bodies()[0].position_dof();
  State state = MakeInitialState(model);
  double worst = 0.0, scale = 0.0;
  DynamicSettings settings = OneOrbit(20000);
  settings.end_time /= 4.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        const Vector3d exact = AnalyticalPosition(r0, v0, s.t);
        worst = std::max(worst, (s.q.segment<3>(x) - exact).norm());
        scale = std::max(scale, exact.norm());
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_LT(worst, 1e-6 * scale);
}

// The pitch libration of a rigid body held by the gravity gradient: with principal moments A
// (radial axis), B (along-track) and C (orbit normal), a small pitch θ about the orbit normal
// obeys θ̈ + 3n² (B − A)/C · θ = 0 (Hughes 1986, "Spacecraft attitude dynamics", §9.2): here
// A = 2, B = 5, C = 6 kg m², ω_θ = n √1.5 = 1.2247 n (without the gravity-gradient torque the
// body would keep its pitch). The period is measured between the upward zero crossings of θ.
TEST(OrbitalFrame, RigidBodyLibratesAtTheGravityGradientPitchFrequency) {
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddRigidBody({.name = "satellite",
                        .mass = 100.0,
                        .inertia = Vector3d(2.0, 5.0, 6.0).asDiagonal(),
                        .orientation = Matrix3d(Eigen::AngleAxisd(0.02, Vector3d::UnitZ()))});
  const Model model = builder.Build();
  const RigidBody& body = model.rigid_bodies()[0];
  const double expected = kMeanMotion * std::sqrt(1.5);
  const double period = 2.0 * std::numbers::pi / expected;
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = period / 400.0;
  settings.end_time = 2.6 * period;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-12;
  State state = MakeInitialState(model);
  std::vector<double> crossings;
  double previous_pitch = 0.0, previous_t = 0.0, jacobi0 = 0.0, worst = 0.0, kinetic = 0.0;
  bool started = false;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount& e) {
        const Matrix3d r = CalcBodyPose(body, s.q, s.body_rotation[0]).R_WB;
        const double pitch = std::atan2(r(1, 0), r(0, 0));
        if (started && previous_pitch < 0.0 && pitch >= 0.0)
          crossings.push_back(previous_t +
                              (s.t - previous_t) * previous_pitch / (previous_pitch - pitch));
        const double jacobi = e.kinetic + e.gravity;
        if (!started) jacobi0 = jacobi;
        started = true;
        worst = std::max(worst, std::abs(jacobi - jacobi0));
        kinetic = std::max(kinetic, e.kinetic);
        previous_pitch = pitch;
        previous_t = s.t;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  ASSERT_GE(crossings.size(), 2u);
  const double measured = 2.0 * std::numbers::pi / (crossings[1] - crossings[0]);
  std::printf("pitch libration %.6f n, expected %.6f n; Jacobi drift %.2e of the kinetic\n",
              measured / kMeanMotion, expected / kMeanMotion, worst / kinetic);
  EXPECT_NEAR(measured, expected, 1e-3 * expected);
  EXPECT_LT(worst, 1e-3 * kinetic);
}

// Euler's equations of a tumbling body integrated in inertial axes, independently of the model's
// Hill-frame terms (classical Runge–Kutta, 0.05 s steps): ω̇ = J⁻¹ (τ − ω × J ω), Ṙ = R ω̃ with
// the gravity-gradient torque τ = 3n² ê × J ê, ê = Rᵀ R_z(nt) e_x. The Hill axes turn at n about
// e_z, so the model's attitude is R_WB = R_z(−nt) R and its rate ω_B = ω − n R_WBᵀ e_z. This
// checks the frame-rate terms too, which do no work and so escape the Jacobi integral.
struct InertialAttitude {
  Matrix3d rotation;
  Vector3d rate;  // body axes
};

InertialAttitude EulerRate(const InertialAttitude& x, const Matrix3d& inertia, double t) {
  const Vector3d radial =
      x.rotation.transpose() *
      (Matrix3d(Eigen::AngleAxisd(kMeanMotion * t, Vector3d::UnitZ())) * Vector3d::UnitX());
  const Vector3d torque = 3.0 * kMeanMotion * kMeanMotion * radial.cross(inertia * radial);
  return {x.rotation * Skew(x.rate), inertia.inverse() * (torque - x.rate.cross(inertia * x.rate))};
}

InertialAttitude IntegrateInInertialAxes(InertialAttitude x, const Matrix3d& inertia, double end) {
  const int steps = static_cast<int>(std::ceil(end / 0.05));
  const double h = end / steps;
  const auto add = [](const InertialAttitude& a, const InertialAttitude& d, double f) {
    return InertialAttitude{a.rotation + f * d.rotation, a.rate + f * d.rate};
  };
  for (int i = 0; i < steps; ++i) {
    const double t = i * h;
    const InertialAttitude k1 = EulerRate(x, inertia, t);
    const InertialAttitude k2 = EulerRate(add(x, k1, 0.5 * h), inertia, t + 0.5 * h);
    const InertialAttitude k3 = EulerRate(add(x, k2, 0.5 * h), inertia, t + 0.5 * h);
    const InertialAttitude k4 = EulerRate(add(x, k3, h), inertia, t + h);
    x.rotation += h / 6.0 * (k1.rotation + 2.0 * k2.rotation + 2.0 * k3.rotation + k4.rotation);
    x.rate += h / 6.0 * (k1.rate + 2.0 * k2.rate + 2.0 * k3.rate + k4.rate);
  }
  return x;
}

TEST(OrbitalFrame, TumblingBodyAttitudeMatchesEulersEquationsInInertialAxes) {
  const Matrix3d inertia = Vector3d(300.0, 400.0, 450.0).asDiagonal();
  const Matrix3d r0(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));
  const Vector3d w0(0.004, 0.003, -0.002);  // relative to the Hill axes, body axes
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddRigidBody({.name = "target",
                        .mass = 500.0,
                        .inertia = inertia,
                        .orientation = r0,
                        .angular_velocity = w0});
  const Model model = builder.Build();
  const RigidBody& body = model.rigid_bodies()[0];
  DynamicSettings settings = OneOrbit(20000);
  settings.end_time /= 4.0;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  const double end = settings.end_time;
  const InertialAttitude inertial = IntegrateInInertialAxes(
      {r0, w0 + kMeanMotion * r0.transpose() * Vector3d::UnitZ()}, inertia, end);
  const Matrix3d hill_to_inertial(Eigen::AngleAxisd(kMeanMotion * end, Vector3d::UnitZ()));
  const Matrix3d expected = hill_to_inertial.transpose() * inertial.rotation;
  const Matrix3d attitude = CalcBodyPose(body, state.q, state.body_rotation[0]).R_WB;
  const Vector3d expected_rate =
      inertial.rate - kMeanMotion * expected.transpose() * Vector3d::UnitZ();
  const Vector3d rate = state.v.segment<3>(body.rotation_dof());
  std::printf("attitude error %.2e rad, rate error %.2e of |ω|\n", (attitude - expected).norm(),
              (rate - expected_rate).norm() / expected_rate.norm());
  // The body turned by about 5 rad relative to the Hill axes.
  EXPECT_LT((attitude - expected).norm(), 1e-5);
  EXPECT_LT((rate - expected_rate).norm(), 1e-5 * expected_rate.norm());
}

// A body tumbling about all three axes while its centre drifts: the Jacobi integral
// ½ m |ẋ|² + ½ ωᵀ J ω + V (forces/orbital_frame_body.hpp) stays constant.
TEST(OrbitalFrame, TumblingBodyKeepsTheJacobiIntegral) {
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddRigidBody(
      {.name = "target",
       .mass = 500.0,
       .inertia = Vector3d(300.0, 400.0, 450.0).asDiagonal(),
       .position = Vector3d(10.0, -5.0, 3.0),
       .orientation = Matrix3d(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized())),
       .velocity = Vector3d(0.01, -0.02, 0.005),
       .angular_velocity = Vector3d(0.004, 0.003, -0.002)});
  const Model model = builder.Build();
  DynamicSettings settings = OneOrbit(2000);
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.end_time /= 4.0;
  const JacobiDrift drift = RunForJacobiDrift(model, settings);
  std::printf("Jacobi drift %.2e of the kinetic energy\n", drift.worst / drift.kinetic);
  EXPECT_LT(drift.worst, 1e-6 * drift.kinetic);
}

}  // namespace
}  // namespace ancfnet
