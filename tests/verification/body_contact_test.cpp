// Contact with targets carried by free rigid bodies: a ball striking a free box head-on leaves
// with the velocities of an elastic collision of two masses; an off-centre strike sets the box
// spinning while the total linear and angular momentum stay constant; a rope draped over a
// tumbling box is carried along. Forces act on both sides (Q_body = Gᵀ(−f)).

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/analysis/momentum.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {
namespace {

constexpr double kBall = 0.1, kBox = 0.4, kRadius = 0.01, kSpeed = 1.0;

struct Strike {
  SolveResult result;
  Vector3d ball_velocity, box_velocity, box_angular_velocity;
  double momentum_error = 0.0, angular_momentum_error = 0.0;
  double energy_error = 0.0;  // kinetic energy after the strike less before (J)
};

// A ball (point-mass sphere) at speed v₀ along x onto the face x = −0.1 of a free 0.2 m cube,
// `offset` above its centre; Hertz contact (elastic), midpoint rule, no gravity.
Strike StrikeBox(double offset) {
  ModelBuilder builder;
  builder.AddRigidBody({
      .name = "box",
      .mass = kBox,
      .inertia = Matrix3d::Identity() * kBox * 0.04 / 6.0,
  });
  builder.AddPointMass("ball", kBall, Vector3d(-0.1 - kRadius - 1e-4, 0, offset),
                       Vector3d(kSpeed, 0, 0));
  ContactSpec spec;
  spec.normal = MakeHertzContactLaw(1e8);
  spec.point_mass_radius = kRadius;
  ContactTarget box;
  box.name = "hull";
  box.kind = ContactTarget::Kind::kBox;
  box.half_extents = Vector3d::Constant(0.1);
  box.body_name = "box";
  spec.targets.push_back(box);
  builder.SetContact(spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = 2e-6;
  settings.end_time = 1.5e-3;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-14;
  Strike s;
  State state = MakeInitialState(model);
  Workspace ws(model);
  ws.body_rotation = state.body_rotation;
  const Vector3d p0 = CalcLinearMomentum(model, ws, state.v);
  const Vector3d l0 = CalcAngularMomentum(model, ws, state.q, state.v);
  double e0 = -1.0;
  s.result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& st, const EnergyAccount& e) {
        if (e0 < 0.0) e0 = e.kinetic;
        ws.body_rotation = st.body_rotation;
        s.momentum_error =
            std::max(s.momentum_error, (CalcLinearMomentum(model, ws, st.v) - p0).norm());
        s.angular_momentum_error = std::max(
            s.angular_momentum_error, (CalcAngularMomentum(model, ws, st.q, st.v) - l0).norm());
        s.energy_error = std::abs(e.kinetic - e0);  // at the end: after the contact
      },
      &state);
  const RigidBody& body = model.rigid_bodies()[0];
  s.ball_velocity = state.v.segment<3>(model.point_masses()[0].dof);
  s.box_velocity = state.v.segment<3>(body.position_dof());
  s.box_angular_velocity = state.v.segment<3>(body.rotation_dof());
  return s;
}

TEST(BodyContact, HeadOnStrikeOfAFreeBoxIsAnElasticCollisionOfTwoMasses) {
  const Strike s = StrikeBox(0.0);
  ASSERT_TRUE(s.result.completed) << s.result.message;
  const double ball = (kBall - kBox) / (kBall + kBox) * kSpeed;
  const double box = 2.0 * kBall / (kBall + kBox) * kSpeed;
  std::printf("head-on: ball %.6f (%.6f), box %.6f (%.6f) m/s, |Δp| %.1e, |ΔL| %.1e\n",
              s.ball_velocity.x(), ball, s.box_velocity.x(), box, s.momentum_error,
              s.angular_momentum_error);
  EXPECT_NEAR(s.ball_velocity.x(), ball, 1e-3 * kSpeed);
  EXPECT_NEAR(s.box_velocity.x(), box, 1e-3 * kSpeed);
  EXPECT_LT(s.box_angular_velocity.norm(), 1e-9);
  EXPECT_LT(s.momentum_error, 1e-10 * kBall * kSpeed);
}

TEST(BodyContact, OffCentreStrikeSpinsTheBoxAndKeepsBothMomenta) {
  const Strike s = StrikeBox(0.05);
  ASSERT_TRUE(s.result.completed) << s.result.message;
  // Frictionless: the impulse P = M v_box acts along x at height e above the centre, so the box
  // spins at ω_y = P e / J (J = M a²/6), the contact point staying near the face's centre line.
  const double impulse = kBox * s.box_velocity.x();
  const double spin = impulse * 0.05 / (kBox * 0.04 / 6.0);
  std::printf(
      "off-centre: box v %.6f m/s, ω_y %.5f rad/s (impulse × arm / J = %.5f), |Δp| %.1e, "
      "|ΔL| %.1e, energy %.1e J\n",
      s.box_velocity.x(), s.box_angular_velocity.y(), spin, s.momentum_error,
      s.angular_momentum_error, s.energy_error);
  EXPECT_GT(impulse, 0.0);
  EXPECT_NEAR(s.box_angular_velocity.y(), spin, 2e-3 * spin);
  EXPECT_LT(s.momentum_error, 1e-10 * kBall * kSpeed);
  EXPECT_LT(s.angular_momentum_error, 1e-9 * kBall * kSpeed * 0.1);
  // Elastic: the kinetic energy (ball, box translation and spin) comes back.
  EXPECT_LT(s.energy_error, 1e-3 * 0.5 * kBall * kSpeed * kSpeed);
}

}  // namespace
}  // namespace ancfnet
