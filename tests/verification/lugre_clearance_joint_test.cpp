// The LuGre (bristle) friction law inside a revolute clearance joint, through the full solver
// (docs/validation.md, "LuGre friction in clearance joints"). A journal (a flywheel on a free
// body) is held by an ideal revolute joint at its centre, pressed into a fixed bearing by
// δ = 10 µm, so that the normal force N = k δ stays constant, and turned by the moment M = m g d
// of its weight, its centre of mass a lever arm d beside the centre:
// - at rest under M = ½ μ_s N R_J it turns by the bristle's pre-sliding, the contact point moving
//   by x = −(μ_s/σ₀) ln(1 − M/(μ_s N R_J)) along the bearing (the quasi-static solution of
//   ż = ẋ (1 − σ₀ z/μ_s) up to σ₀ N z R_J = M, as for the block on an incline), and stops: the
//   bristle then holds the friction moment M;
// - spinning under M = 1.2 μ_k N R_J (below μ_s N R_J) it keeps sliding, the friction moment
//   μ_k N R_J (Coulomb at the kinetic coefficient, well above the Stribeck speed), and its
//   angular acceleration is (M cos θ − μ_k N R_J)/J about the held centre;
// both with kinetic + strain + gravity + dissipated constant within 1 % of the energy the
// friction takes. explicit_verlet refuses the law in a joint as it does in contact.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {
namespace {

constexpr double kG = 9.81;
constexpr double kClearance = 1e-3;              // c (m)
constexpr double kJournalRadius = 0.02;          // R_J (m)
constexpr double kStiffness = 1e7;               // of the linear normal law (N/m)
constexpr double kDepth = 1e-5;                  // δ (m), held by the ideal joint
constexpr double kNormal = kStiffness * kDepth;  // N = 100 N
constexpr double kMass = 1.0;                    // kg
constexpr double kSpinInertia = 0.1;             // J_zz about the centre of mass (kg m²)
constexpr double kMuS = 0.4, kMuK = 0.3;
constexpr double kSigma0 = 1e4;  // 1/m
// The bristle holds the journal with the torsional stiffness N σ₀ R_J² = 400 N m/rad, at
// ω_b ≈ 63 rad/s; σ₁ = 2 √(J σ₀/(N R_J²)) damps it critically.
constexpr double kSigma1 = 316.0;  // s/m
// A Stribeck speed above the pre-sliding speeds (below 1 mm/s), below the spinning slip (4 cm/s).
constexpr double kStribeckSpeed = 1e-2;

FrictionLaw LuGre() { return MakeLuGreFriction(kMuS, kMuK, kStribeckSpeed, kSigma0, kSigma1, 0.0); }

// The journal's centre, pressed δ into the bearing (centre at the origin) along −y.
const Vector3d kCenter(0.0, -(kClearance + kDepth), 0.0);

// The journal turned by its weight's moment `moment` (its centre of mass d = M/(m g) along +x
// of its centre), spinning at `spin` = ω₀ about z; `held` by the ideal joint at its centre.
Model MakeJournal(double moment, double spin, bool held = true) {
  const double arm = moment / (kMass * kG);
  const Vector3d offset(arm, 0.0, 0.0);
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, -kG, 0));
  builder.AddRigidBody(
      {.name = "journal",
       .mass = kMass,
       .inertia = Vector3d(0.5 * kSpinInertia, 0.5 * kSpinInertia, kSpinInertia).asDiagonal(),
       .position = kCenter + offset,
       .velocity = Vector3d(0, 0, spin).cross(offset),
       .angular_velocity = Vector3d(0, 0, spin)});
  if (held)
    builder.AddIdealJoint({.name = "axle",
                           .type = IdealJoint::Type::kRevolute,
                           .first = {.kind = JointAnchor::Kind::kGround},
                           .second = {.kind = JointAnchor::Kind::kBody, .name = "journal"},
                           .point = kCenter,
                           .axis = Vector3d::UnitZ()});
  builder.AddClearanceJoint(
      {.name = "pin",
       .type = ClearanceJoint::Type::kRevolute,
       .journal = {.kind = JointAnchor::Kind::kBody, .name = "journal", .position = kCenter},
       .bearing = {.kind = JointAnchor::Kind::kGround, .position = Vector3d::Zero()},
       .clearance = kClearance,
       .journal_radius = kJournalRadius,
       .normal = MakeLinearContactLaw(kStiffness, 0.0),
       .friction = LuGre()});
  return builder.Build();
}

struct Turn {
  double angle = 0.0;              // θ of the journal about z at the end (rad)
  double spin = 0.0;               // ω_z at the end (rad/s)
  double spin_rate = 0.0;          // ω̇_z at the end (rad/s²)
  double max_balance_error = 0.0;  // max |balance − balance₀| (J)
  double dissipated = 0.0;         // by the end (J)
  ClearanceContact contact;        // at the end, with the stored bristle (h = 0)
};

// Generalised-α with steps h up to `end_time`, from the initial state with the joint's stored
// bristle `bristle` (world axes: the bearing is the ground).
Turn Simulate(const Model& model, double h, double end_time, const Vector3d& bristle) {
  DynamicSettings settings;
  settings.integrator = IntegratorType::kGeneralizedAlpha;
  settings.time_step = h;
  settings.end_time = end_time;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-14;
  State state = MakeInitialState(model);
  state.joint_history[0].bristle = bristle;
  Turn turn;
  bool first = true;
  double balance0 = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State&, const EnergyAccount& e) {
        if (first) balance0 = e.Balance(), first = false;
        turn.max_balance_error = std::max(turn.max_balance_error, std::abs(e.Balance() - balance0));
        turn.dissipated = e.dissipated;
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  const RigidBody& body = model.rigid_bodies()[0];
  const Matrix3d R = CalcBodyPose(body, state.q, state.body_rotation[0]).R_WB;
  turn.angle = std::atan2(R(1, 0), R(0, 0));
  turn.spin = (R * CalcBodyVelocity(body, state.v).w_B).z();
  turn.spin_rate = (R * state.a.segment<3>(body.rotation_dof())).z();
  turn.contact = CalcClearanceJointState(model, 0, state.q, state.v, state.body_rotation,
                                         state.joint_history[0])
                     .contact;
  return turn;
}

TEST(LuGreClearanceJoint, JournalBelowTheStaticMomentPreSlidesAndSticks) {
  const double moment = 0.5 * kMuS * kNormal * kJournalRadius;  // 0.4 N m
  const Turn turn = Simulate(MakeJournal(moment, 0.0), 1e-3, 1.0, Vector3d::Zero());
  const double slip = -kJournalRadius * turn.angle;  // the contact point's arc (turning −z)
  const double expected =
      -(kMuS / kSigma0) * std::log(1.0 - moment / (kMuS * kNormal * kJournalRadius));
  const double work = moment * std::abs(turn.angle);  // of the weight
  std::printf(
      "LuGre journal, M = ½ μ_s N R: pre-slides %.4e m (expected %.4e m), ω = %.2e rad/s "
      "after 1 s, friction moment %.6e N m (M cos θ = %.6e), energy error %.2e of %.3e J\n",
      slip, expected, turn.spin, turn.contact.journal_moment.z(), moment * std::cos(turn.angle),
      turn.max_balance_error / work, work);
  ASSERT_TRUE(turn.contact.touching);
  EXPECT_NEAR(turn.contact.normal_force, kNormal, 1e-6 * kNormal);
  EXPECT_NEAR(slip / expected, 1.0, 0.15);
  EXPECT_LT(std::abs(turn.spin) * kJournalRadius, 1e-6);
  // At rest the bristle holds the weight's moment.
  EXPECT_NEAR(turn.contact.journal_moment.z(), moment * std::cos(turn.angle), 1e-3 * moment);
  EXPECT_LT(turn.max_balance_error, 1e-2 * work);
}

TEST(LuGreClearanceJoint, SpinningJournalAboveTheKineticMomentSlidesAtMuKNR) {
  const double kinetic = kMuK * kNormal * kJournalRadius;  // 0.6 N m
  const double moment = 1.2 * kinetic;                     // below μ_s N R_J = 0.8 N m
  const double spin = -2.0;  // rad/s: the slip R_J ω₀ = 4 cm/s, 4 v_s
  const Model model = MakeJournal(moment, spin);
  // Sliding steadily from the start: the contact point (at −R_J y) slips along ω₀ z × (−R_J y)
  // = R_J ω₀ x, the bristle at its steady deflection z_ss = g(s) v̂/σ₀ (g(4 v_s) = μ_k to 10⁻⁷).
  // Started at zero it would load within 1/φ = g/(σ₀ s) ≈ 0.75 ms, the damping σ₁ N ż of that
  // loading braking the journal by ≈ σ₁ N z_ss R_J/J = 0.18 rad/s.
  const Turn turn =
      Simulate(model, 1e-3, 0.1, Vector3d(std::copysign(kMuK / kSigma0, spin), 0.0, 0.0));
  const double arm = moment / (kMass * kG);
  const double inertia = kSpinInertia + kMass * arm * arm;  // about the held centre
  // The friction moment the motion shows: J ω̇ = −M cos θ + M_f.
  const double from_motion = inertia * turn.spin_rate + moment * std::cos(turn.angle);
  std::printf(
      "LuGre journal, M = 1.2 μ_k N R spinning: ω = %.4f rad/s, friction moment %.6e N m, "
      "from the motion %.6e N m (μ_k N R = %.6e), energy error %.2e of %.3e J\n",
      turn.spin, turn.contact.journal_moment.z(), from_motion, kinetic,
      turn.max_balance_error / turn.dissipated, turn.dissipated);
  ASSERT_TRUE(turn.contact.touching);
  EXPECT_LT(turn.spin, spin);  // still sliding, faster
  EXPECT_NEAR(turn.contact.journal_moment.z(), kinetic, 1e-2 * kinetic);
  EXPECT_NEAR(from_motion, kinetic, 1e-2 * kinetic);
  EXPECT_LT(turn.max_balance_error, 1e-2 * turn.dissipated);
}

TEST(LuGreClearanceJoint, ExplicitIntegratorRefusesTheLaw) {
  const Model model = MakeJournal(0.1, 0.0, /*held=*/false);  // (Verlet refuses ideal joints)
  DynamicSettings settings;
  settings.integrator = IntegratorType::kExplicitVerlet;
  State state = MakeInitialState(model);
  try {
    SolveDynamic(
        model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state);
    ADD_FAILURE() << "explicit_verlet accepted LuGre friction in a joint";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("joint 'pin' friction: the LuGre law needs"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace ancfnet
