// Beams in the Hill frame of a circular orbit (forces/orbital_frame.hpp; docs/theory.md, "Beams
// in an orbital frame"):
//  - a thin beam tether moves as the cable tether of the same thread (bending, shear and the
//    sections' rotary inertia do not matter there) and keeps the Jacobi integral;
//  - a thick stiff rod librates in pitch about the local vertical with the rigid body's
//    frequency ω² = 3n² (I_t − I_a)/I_t (Hughes 1986), I_t = m (L²/12 + r²/4) and
//    I_a = m r²/2: the sections' own inertia enters through the frame's forces on d₂, d₃. With the
//    frame acting on the centre line only, ω would be 11 % higher (ω² = 3n² m L²/12 / I_t).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kMeanMotion = 0.0011;  // rad/s, a low Earth orbit
constexpr double kPeriod = 2.0 * std::numbers::pi / kMeanMotion;

DynamicSettings Conservative(double time_step, double end_time) {
  DynamicSettings settings;
  settings.spectral_radius = 1.0;
  settings.time_step = time_step;
  settings.end_time = end_time;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-12;
  return settings;
}

// The tether of OrbitalFrame.FreeCableKeepsTheJacobiIntegral: 20 m of 4 mm, E = 1 GPa, turning
// at 0.002 rad/s about its middle while drifting along-track; a beam when `beam`.
Model Tether(bool beam) {
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  CableSpec spec{.name = "tether",
                 .start = Vector3d(5.0, 0.0, 0.0),
                 .end = Vector3d(25.0, 0.0, 0.0),
                 .num_elements = 4,
                 .properties = MakeCableProperties({.youngs_modulus = 1e9, .density = 1400},
                                                   MakeCircleSection(0.004))};
  if (beam)
    spec.beam =
        BeamCableSpec{.material = {.youngs_modulus = 1e9, .poisson_ratio = 0.3, .density = 1400},
                      .section = MakeCircleBeamSection(0.004, 0.3),
                      .orientation = Vector3d::UnitY()};
  builder.AddCable(spec);
  builder.SetInitialVelocity("tether", Vector3d(0.0, 0.01, 0.0), Vector3d(0, 0, 0.002),
                             Vector3d(15.0, 0.0, 0.0));
  return builder.Build();
}

struct Flight {
  State state;
  double jacobi_drift = 0.0;  ///< max |J − J₀| (J)
  double kinetic = 0.0;       ///< max kinetic energy (J)
};

Flight Fly(const Model& model, const DynamicSettings& settings) {
  Flight flight{MakeInitialState(model)};
  bool started = false;
  double first = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State&, const EnergyAccount& e) {
        const double jacobi = e.kinetic + e.strain + e.gravity;  // gravity: the tidal potential
        if (!started) first = jacobi;
        started = true;
        flight.jacobi_drift = std::max(flight.jacobi_drift, std::abs(jacobi - first));
        flight.kinetic = std::max(flight.kinetic, e.kinetic);
      },
      &flight.state);
  EXPECT_TRUE(result.completed) << result.message;
  return flight;
}

TEST(BeamOrbit, BeamTetherMovesAsTheCableTether) {
  const DynamicSettings settings = Conservative(kPeriod / 2000.0, kPeriod / 4.0);
  const Model cable_model = Tether(false), beam_model = Tether(true);
  const Flight cable = Fly(cable_model, settings);
  const Flight beam = Fly(beam_model, settings);
  double worst = 0.0, travel = 0.0;
  for (std::size_t i = 0; i < cable_model.nodes().size(); ++i) {
    const Index c = cable_model.nodes()[i].position_dof, b = beam_model.nodes()[i].position_dof;
    worst = std::max(worst, (cable.state.q.segment<3>(c) - beam.state.q.segment<3>(b)).norm());
    travel = std::max(
        travel, (beam.state.q.segment<3>(b) - beam_model.initial_positions().segment<3>(b)).norm());
  }
  std::printf(
      "tether after a quarter orbit: nodes moved up to %.3f m, beam - cable %.3e m; "
      "beam Jacobi drift %.2e of the kinetic energy\n",
      travel, worst, beam.jacobi_drift / beam.kinetic);
  EXPECT_GT(travel, 10.0);
  EXPECT_LT(worst, 1e-7 * travel);
  EXPECT_LT(beam.jacobi_drift, 2e-6 * beam.kinetic);
}

TEST(BeamOrbit, ThickRodLibratesWithTheRigidBodyPitchFrequency) {
  // L = 2 m, d = 1 m, E = 10 GPa: a rigid cylinder; tilted by 0.05 rad in the orbit plane, at
  // rest in the Hill frame, centred on the origin.
  const double length = 2.0, radius = 0.5, tilt = 0.05;
  const Vector3d axis(std::cos(tilt), std::sin(tilt), 0.0);
  ModelBuilder builder;
  builder.SetOrbitalFrame(kMeanMotion);
  builder.AddCable({.name = "rod",
                    .start = -0.5 * length * axis,
                    .end = 0.5 * length * axis,
                    .num_elements = 2,
                    .properties = MakeCableProperties({.youngs_modulus = 1e10, .density = 1000},
                                                      MakeCircleSection(2.0 * radius)),
                    .beam = BeamCableSpec{
                        .material = {.youngs_modulus = 1e10, .poisson_ratio = 0.3, .density = 1000},
                        .section = MakeCircleBeamSection(2.0 * radius, 0.3),
                        .orientation = Vector3d::UnitY()}});
  const Model model = builder.Build();
  const double transverse = length * length / 12.0 + radius * radius / 4.0;  // I_t / m
  const double axial = radius * radius / 2.0;                                // I_a / m
  const double omega = kMeanMotion * std::sqrt(3.0 * (transverse - axial) / transverse);
  const double quarter = 0.5 * std::numbers::pi / omega;
  State state = MakeInitialState(model);
  const Index tip = model.nodes().back().position_dof;
  // The first zero of the pitch angle θ(t) = θ₀ cos ωt, interpolated between steps.
  double crossing = 0.0, previous_angle = tilt, previous_time = 0.0;
  double first = 0.0, drift = 0.0, kinetic = 0.0;
  bool started = false;
  const SolveResult result = SolveDynamic(
      model, Conservative(quarter / 200.0, 1.1 * quarter), 0.0,
      [&](const State& s, const EnergyAccount& e) {
        const double jacobi = e.kinetic + e.strain + e.gravity;
        if (!started) first = jacobi;
        started = true;
        drift = std::max(drift, std::abs(jacobi - first));
        kinetic = std::max(kinetic, e.kinetic);
        const double angle = std::atan2(s.q[tip + 1], s.q[tip]);
        if (crossing == 0.0 && angle <= 0.0 && previous_angle > 0.0)
          crossing =
              previous_time + (s.t - previous_time) * previous_angle / (previous_angle - angle);
        previous_angle = angle;
        previous_time = s.t;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  ASSERT_GT(crossing, 0.0);
  // θ̈ = −(ω²/2) sin 2θ is a pendulum in 2θ: its quarter period grows by (2θ₀)²/16.
  const double measured = 0.5 * std::numbers::pi / crossing * (1.0 + 4.0 * tilt * tilt / 16.0);
  std::printf(
      "thick rod: pitch libration %.6f n, amplitude-corrected (rigid body %.6f n, centre "
      "line only %.6f n); Jacobi drift %.2e of the kinetic energy\n",
      measured / kMeanMotion, omega / kMeanMotion,
      std::sqrt(3.0 * length * length / 12.0 / transverse), drift / kinetic);
  EXPECT_NEAR(measured / omega, 1.0, 1e-4);
  // The sections' tidal potential swings by 0.2 of the kinetic energy: left out of the Jacobi
  // integral (or its force left out of the equations), it would show.
  EXPECT_LT(drift, 1e-3 * kinetic);
}

}  // namespace
}  // namespace ancfnet
