// Clearance joints through the full solver (docs/validation.md, "Clearance joints"):
// - a rigid journal released with a velocity inside a bearing with an elastic (Hertz) law and no
//   friction bounces with its energy conserved, and its first impact reaches the Hertz depth
//   δ_max = (5 m v²/(4k))^(2/5) (Johnson 1985, §11.4; Lankarani & Nikravesh 1990);
// - a journal pressed by a constant load (its weight) settles where the law's force equals the
//   load, δ = (m g/k)^(1/n), with kinetic + strain + gravity + dissipated − work constant;
// - a bearing (a point mass) hanging on a journal spinning with Coulomb friction stays at the
//   friction angle φ = atan μ, where the friction moment on the journal is μ N R_J with
//   N = m g/√(1 + μ²) (the friction circle of a journal bearing; Flores & Ambrósio 2004);
// - a ball flying across a spherical clearance socket rebounds from the socket's wall with the
//   restitution e* its dissipative law achieves in a free impact, the root of
//   χ̂ (1 + e*) = ln[(1 + χ̂)/(1 − χ̂ e*)] (CalcRestitutionForHysteresisFactor, docs/theory.md),
//   and the energy the law dissipates is the kinetic energy lost, ½ m v₀² (1 − e*²).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"

namespace ancfnet {
namespace {

constexpr double kClearance = 1e-3;      // c (m)
constexpr double kJournalRadius = 0.02;  // R_J (m)
constexpr double kMass = 1.0;            // the journal's (kg)

RigidBodySpec Journal(const Vector3d& velocity, const Vector3d& angular_velocity) {
  return {.name = "journal",
          .mass = kMass,
          .inertia = Vector3d(2e-4, 2e-4, 2e-4).asDiagonal(),
          .velocity = velocity,
          .angular_velocity = angular_velocity};
}

// A journal on a free body in a bearing fixed to the ground (centre at the origin, axis z).
ClearanceJointSpec GroundBearing(const NormalLaw& law, const std::optional<FrictionLaw>& friction) {
  return {.name = "pin",
          .type = ClearanceJoint::Type::kRevolute,
          .journal = {.kind = JointAnchor::Kind::kBody, .name = "journal"},
          .bearing = {.kind = JointAnchor::Kind::kGround},
          .clearance = kClearance,
          .journal_radius = kJournalRadius,
          .normal = law,
          .friction = friction};
}

struct JointRun {
  double max_penetration = 0.0;    // of the first impact (m)
  double max_balance_error = 0.0;  // max |balance − balance₀| (J)
  double energy0 = 0.0;            // kinetic + strain at t = 0 (J)
  int impacts = 0;                 // contacts started
  double dissipated = 0.0;         // by the end (J)
  ClearanceJointState last;
  State state;
};

JointRun Simulate(const Model& model, IntegratorType integrator, double h, double end_time) {
  DynamicSettings settings;
  settings.integrator = integrator;
  settings.time_step = h;
  settings.end_time = end_time;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-14;
  JointRun run;
  run.state = MakeInitialState(model);
  bool first = true, touching = false;
  double balance0 = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount& e) {
        if (first) balance0 = e.Balance(), run.energy0 = e.kinetic + e.strain, first = false;
        run.max_balance_error = std::max(run.max_balance_error, std::abs(e.Balance() - balance0));
        run.dissipated = e.dissipated;
        run.last = CalcClearanceJointState(model, 0, s.q, s.v, s.body_rotation, s.joint_history[0]);
        const bool now = run.last.contact.touching;
        if (now && !touching) ++run.impacts;
        if (now && run.impacts == 1)
          run.max_penetration = std::max(run.max_penetration, run.last.contact.penetration);
        touching = now;
      },
      &run.state);
  EXPECT_TRUE(result.completed) << result.message;
  return run;
}

TEST(ClearanceJoint, ElasticJournalBouncesWithItsEnergyAndTheHertzDepth) {
  const NormalLaw hertz = MakeHertzContactLaw(1e9, 1.5);
  const Vector3d v0(0.3, 0.17, 0.0);
  ModelBuilder builder;
  builder.AddRigidBody(Journal(v0, Vector3d(0, 0, 5.0)));
  builder.AddClearanceJoint(GroundBearing(hertz, std::nullopt));
  const Model model = builder.Build();
  const JointRun run = Simulate(model, IntegratorType::kImplicitMidpoint, 1e-5, 0.05);
  // Released at the centre, it strikes head-on: v_n = |v₀|.
  const double expected = std::pow(5.0 * kMass * v0.squaredNorm() / (4.0 * 1e9), 0.4);
  std::printf("elastic journal: %d impacts, first depth %.6e m (Hertz %.6e), energy error %.2e\n",
              run.impacts, run.max_penetration, expected, run.max_balance_error / run.energy0);
  EXPECT_GE(run.impacts, 5);
  EXPECT_NEAR(run.max_penetration, expected, 1e-2 * expected);
  EXPECT_LT(run.max_balance_error, 1e-3 * run.energy0);
}

TEST(ClearanceJoint, LoadedJournalSettlesWhereTheLawBalancesTheLoad) {
  // Lankarani–Nikravesh, e = 0.5: the journal falls across the clearance, bounces and settles.
  const double k = 5e8;
  const NormalLaw law = MakeDissipativeContactLaw(NormalLawKind::kLankaraniNikravesh, k, 0.5);
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, -9.81, 0));
  builder.AddRigidBody(Journal(Vector3d::Zero(), Vector3d(0, 0, 2.0)));
  builder.AddClearanceJoint(GroundBearing(law, std::nullopt));
  const Model model = builder.Build();
  const JointRun run = Simulate(model, IntegratorType::kImplicitMidpoint, 2e-5, 0.3);
  const double expected = std::pow(kMass * 9.81 / k, 1.0 / 1.5);
  const ClearanceContact& c = run.last.contact;
  // The balance, with the bounces' dissipation, within 1 % of the energy of the fall.
  const double fall = kMass * 9.81 * kClearance + run.energy0;
  std::printf(
      "loaded journal: %d impacts, δ = %.6e m (expected %.6e), F_n = %.6f N, energy "
      "error %.2e of the fall's %.3e J\n",
      run.impacts, c.penetration, expected, c.normal_force, run.max_balance_error / fall, fall);
  ASSERT_TRUE(c.touching);
  EXPECT_EQ(run.last.mode, ClearanceMode::kContact);
  EXPECT_NEAR(c.penetration, expected, 1e-3 * expected);
  EXPECT_NEAR(c.normal_force, kMass * 9.81, 1e-3 * kMass * 9.81);
  EXPECT_LT(run.max_balance_error, 1e-2 * fall);
}

TEST(ClearanceJoint, FrictionMomentOfASpinningJournalIsMuNR) {
  // The journal spins at 20 rad/s on a fixed axis; the bearing, a 2 kg point mass, hangs on it.
  const double mu = 0.2, m = 2.0, g = 9.81, omega = 20.0;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, -g, 0));
  RigidBodySpec journal = Journal(Vector3d::Zero(), Vector3d(0, 0, omega));
  journal.motion = BodyMotion::kPrescribed;
  builder.AddRigidBody(journal);
  // It starts at rest where it should stay: at φ = atan μ from below the journal, pressed in by
  // the penetration that carries N. Wrong friction forces or moments would move it away.
  const double k = 1e8;
  const double normal = m * g / std::sqrt(1.0 + mu * mu);
  const double depth = std::pow(normal / k, 1.0 / 1.5);
  const double phi = std::atan(mu);
  // e = c_J − c_B along n: the journal's surface drags the bearing towards −x.
  const Vector3d n(std::sin(phi), std::cos(phi), 0.0);
  builder.AddPointMass("bearing", m, -(kClearance + depth) * n);
  ClearanceJointSpec spec =
      GroundBearing(MakeDissipativeContactLaw(NormalLawKind::kLankaraniNikravesh, k, 0.3),
                    MakeAmbrosioFriction(mu, 1e-4, 1e-3));
  spec.bearing = {.kind = JointAnchor::Kind::kPoint, .name = "bearing"};
  builder.AddClearanceJoint(spec);
  const Model model = builder.Build();
  const JointRun run = Simulate(model, IntegratorType::kGeneralizedAlpha, 1e-4, 0.2);
  const ClearanceContact& c = run.last.contact;
  ASSERT_TRUE(c.touching);
  const double moment = mu * normal * kJournalRadius;
  // The bearing below the journal, turned towards the slip by the friction angle.
  const double angle = std::atan2(-c.eccentricity.x(), c.eccentricity.y());
  std::printf(
      "spinning journal: N = %.6f N (expected %.6f), M = %.6e N m (expected %.6e), "
      "angle %.5f rad (atan μ = %.5f)\n",
      c.normal_force, normal, c.journal_moment.z(), -moment, angle, std::atan(mu));
  EXPECT_NEAR(c.normal_force, normal, 1e-2 * normal);
  // Friction on the journal opposes its spin: M_z = −μ N R_J.
  EXPECT_NEAR(c.journal_moment.z(), -moment, 1e-2 * moment);
  EXPECT_NEAR(std::abs(angle), std::atan(mu), 1e-2 * std::atan(mu));
}

TEST(ClearanceJoint, BallInASphericalSocketReboundsWithItsLawsRestitution) {
  // The ball (the journal, a free body) leaves the socket's centre along an oblique direction
  // at 0.5 m/s, strikes the wall head-on after c/v₀ and flies back; the run ends 3 Hertz contact
  // times after the strike, before the ball can reach the opposite wall (2c/(e* v₀) later).
  const double speed = 0.5, k = 1e9;
  const Vector3d v0 = speed * Vector3d(0.6, 0.48, 0.64);
  const double delta_max = std::pow(5.0 * kMass * speed * speed / (4.0 * k), 0.4);
  const double hertz_time = 2.943275 * delta_max / speed;  // Johnson 1985, §11.4
  for (const auto& [kind, e] :
       {std::pair(NormalLawKind::kLankaraniNikravesh, 0.5), std::pair(NormalLawKind::kFlores, 0.7),
        std::pair(NormalLawKind::kHuntCrossley, 0.9)}) {
    const NormalLaw law = MakeDissipativeContactLaw(kind, k, e);
    ModelBuilder builder;
    builder.AddRigidBody(Journal(v0, Vector3d(0, 0, 3.0)));
    ClearanceJointSpec socket = GroundBearing(law, std::nullopt);
    socket.type = ClearanceJoint::Type::kSpherical;
    builder.AddClearanceJoint(socket);
    const Model model = builder.Build();
    const JointRun run = Simulate(model, IntegratorType::kImplicitMidpoint, hertz_time / 1000.0,
                                  kClearance / speed + 3.0 * hertz_time);
    const Index dof = model.rigid_bodies()[0].position_dof();
    const Vector3d rebound = run.state.v.segment<3>(dof);
    const double restitution = rebound.norm() / speed;
    const double expected = CalcRestitutionForHysteresisFactor(law.hysteresis_factor());
    const double loss = 0.5 * kMass * speed * speed * (1.0 - expected * expected);
    std::printf(
        "ball in socket, law %d, e = %.1f: rebound %.5f of v₀ (predicted e* = %.5f), "
        "direction cos %.6f, dissipated %.6e J (½ m v₀² (1 − e*²) = %.6e J), %d impact\n",
        static_cast<int>(kind), e, restitution, expected,
        rebound.dot(v0) / (rebound.norm() * speed), run.dissipated, loss, run.impacts);
    EXPECT_EQ(run.impacts, 1);
    EXPECT_FALSE(run.last.contact.touching);
    EXPECT_NEAR(restitution, expected, 5e-3 * expected);
    EXPECT_LT(rebound.dot(v0) / (rebound.norm() * speed), -0.9999);  // straight back
    EXPECT_NEAR(run.dissipated, loss, 1e-2 * loss);
  }
}

}  // namespace
}  // namespace ancfnet
