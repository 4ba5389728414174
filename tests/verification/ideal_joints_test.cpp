// Ideal joints (constraints with Lagrange multipliers) through the solvers:
// - a rigid pendulum on a revolute or spherical joint to the ground: small-amplitude period
//   T = 2π √(I_O/(m g d)) (1 + θ₀²/16 + 11 θ₀⁴/3072) (the series of the complete elliptic
//   integral), energy constant and the joint's drift |g| within Newton's tolerance;
// - the ideal slider-crank of Flores & Ambrósio (crank r = 0.05 m, rod l = 0.12 m, 5000 rpm):
//   the slider's acceleration −r ω² (1 + r/l) at θ = 0 and r ω² (1 − r/l) at θ = π, the
//   slider on a line or a prismatic joint; a block sliding down an incline on a prismatic joint;
// - statics: an ANCF cable pinned by spherical joints to the ground and to a fixed body carries
//   its weight and a load; the joints' reactions balance them;
// - a strip welded to a fixed body bends as the builder's clamped cantilever, and a strip
//   pendulum on a spherical joint swings as on the builder's pin;
// - modal analysis with joints: strips held by joints have the modes of the builder's supports;
// - a body on a revolute joint about a cable's tangent spins freely about it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/modal.hpp"
#include "ancfnet/state/rigid_body_state.hpp"
#include "ancfnet/solvers/static_solver.hpp"
#include "slider_crank.hpp"

namespace ancfnet {
namespace {

constexpr double kPi = std::numbers::pi;

// ---- Pendulum -------------------------------------------------------------------------------

constexpr double kMass = 2.0;       // m (kg)
constexpr double kArm = 0.5;        // d: pivot to centre of mass (m)
constexpr double kInertiaZ = 0.03;  // about the centre of mass (kg m²)
constexpr double kGravity = 9.81;
constexpr double kAmplitude = 0.05;  // θ₀ (rad)

double PendulumPeriod() {
  const double inertia = kInertiaZ + kMass * kArm * kArm;  // about the pivot
  const double t0 = 2.0 * kPi * std::sqrt(inertia / (kMass * kGravity * kArm));
  const double a2 = kAmplitude * kAmplitude;
  return t0 * (1.0 + a2 / 16.0 + 11.0 * a2 * a2 / 3072.0);
}

// The body hangs from the pivot at the origin, released from rest at θ₀ about z.
Model MakePendulum(IdealJoint::Type type) {
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, -kGravity, 0));
  const Matrix3d rotation(Eigen::AngleAxisd(kAmplitude, Vector3d::UnitZ()));
  builder.AddRigidBody({.name = "bob",
                        .mass = kMass,
                        .inertia = Vector3d(0.01, 0.02, kInertiaZ).asDiagonal(),
                        .position = rotation * Vector3d(0, -kArm, 0),
                        .orientation = rotation});
  builder.AddIdealJoint({.name = "pivot",
                         .type = type,
                         .first = {.kind = JointAnchor::Kind::kGround},
                         .second = {.kind = JointAnchor::Kind::kBody, .name = "bob"},
                         .point = Vector3d::Zero(),
                         .axis = Vector3d::UnitZ()});
  return builder.Build();
}

void ExpectPendulumSwingsAsTheClosedForm(IdealJoint::Type type, const char* label) {
  const Model model = MakePendulum(type);
  const double period = PendulumPeriod();
  DynamicSettings settings;
  settings.time_step = period / 400.0;
  settings.end_time = 3.0 * period;
  settings.spectral_radius = 0.9;
  State state = MakeInitialState(model);
  std::vector<double> crossings;  // times the centre of mass passes x = 0 going −x
  double previous_x = 0.0, previous_t = 0.0;
  double e0 = 0.0, max_drift = 0.0;
  bool first = true;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount& energy) {
        const double x = s.q[0];
        if (first) {
          e0 = energy.Balance();
          first = false;
        } else if (previous_x > 0.0 && x <= 0.0) {
          crossings.push_back(previous_t + (s.t - previous_t) * previous_x / (previous_x - x));
        }
        max_drift = std::max(max_drift, std::abs(energy.Balance() - e0));
        previous_x = x;
        previous_t = s.t;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  ASSERT_GE(crossings.size(), 3u);
  const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1.0);
  // The energy of the swing, m g d (1 − cos θ₀), is the scale of the energy drift.
  const double swing = kMass * kGravity * kArm * (1.0 - std::cos(kAmplitude));
  std::printf(
      "%s pendulum: period %.6f s (closed form %.6f s, error %.2e), energy drift %.2e of the "
      "swing's energy, largest |g| %.2e m\n",
      label, measured, period, measured / period - 1.0, max_drift / swing,
      result.statistics.max_constraint_violation);
  EXPECT_NEAR(measured / period, 1.0, 5e-3);
  EXPECT_LT(max_drift, 1e-3 * swing);
  // Newton's tolerance on a position equation at the origin: atol = 1e-8 m.
  EXPECT_LT(result.statistics.max_constraint_violation, settings.newton.absolute_tolerance);
}

TEST(IdealJoints, PendulumOnARevoluteJointSwingsWithTheClosedFormPeriod) {
  ExpectPendulumSwingsAsTheClosedForm(IdealJoint::Type::kRevolute, "revolute");
}

TEST(IdealJoints, PendulumOnASphericalJointSwingsWithTheClosedFormPeriod) {
  ExpectPendulumSwingsAsTheClosedForm(IdealJoint::Type::kSpherical, "spherical");
}

TEST(IdealJoints, OtherIntegratorsRefuseJoints) {
  const Model model = MakePendulum(IdealJoint::Type::kRevolute);
  for (IntegratorType integrator :
       {IntegratorType::kImplicitMidpoint, IntegratorType::kExplicitVerlet}) {
    DynamicSettings settings;
    settings.integrator = integrator;
    State state = MakeInitialState(model);
    try {
      SolveDynamic(model, settings, 0.0, {}, &state);
      ADD_FAILURE() << "an integrator without constraints accepted ideal joints";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("does not support ideal joints"), std::string::npos)
          << error.what();
    }
  }
}

// ---- Slider-crank ---------------------------------------------------------------------------

using namespace verification::slider_crank;

// The crank a prescribed body turning at ω about z, the rod a free body, the slider a free body
// guided along the x axis, spherical joints at the crank pin and the piston pin. With a line
// joint as the guide: 8 equations on 12 coordinates, leaving the rod's spin about its own axis
// and the slider's rotation free (and at rest); with a prismatic joint, 11 equations, the
// slider's rotation locked. None of them redundant.
Model MakeSliderCrank(IdealJoint::Type guide) {
  ModelBuilder builder;
  AddCrankAndRod(&builder);
  const Vector3d pin(kCrank + kRod, 0, 0);
  builder.AddRigidBody({.name = "slider",
                        .mass = 0.14,
                        .inertia = Vector3d(1e-5, 1e-5, 1e-5).asDiagonal(),
                        .position = pin});
  using Kind = JointAnchor::Kind;
  builder.AddIdealJoint({.name = "crank_pin",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = Kind::kBody, .name = "crank"},
                         .second = {.kind = Kind::kBody, .name = "rod"},
                         .point = Vector3d(kCrank, 0, 0)});
  builder.AddIdealJoint({.name = "piston_pin",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = Kind::kBody, .name = "rod"},
                         .second = {.kind = Kind::kBody, .name = "slider"},
                         .point = pin});
  builder.AddIdealJoint({.name = "guide",
                         .type = guide,
                         .first = {.kind = Kind::kBody, .name = "slider"},
                         .second = {.kind = Kind::kGround},
                         .point = pin,
                         .axis = Vector3d::UnitX()});
  return builder.Build();
}

void ExpectSliderAccelerationAsTheKinematics(IdealJoint::Type guide, const char* label) {
  const Model model = MakeSliderCrank(guide);
  const Index slider_x = model.rigid_bodies()[2].position_dof();
  const DynamicSettings settings = MakeSliderCrankSettings(2.5, 0.6);
  State state = MakeInitialState(model);
  double at_0 = 0.0, at_pi = 0.0, best_0 = 1.0, best_pi = 1.0;
  EnergyAccount first_energy, last_energy;
  bool first = true;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount& energy) {
        if (first) first_energy = energy, first = false;
        last_energy = energy;
        if (std::abs(s.t - 2.0 * kPeriod) < best_0)
          best_0 = std::abs(s.t - 2.0 * kPeriod), at_0 = s.a[slider_x];
        if (std::abs(s.t - 2.5 * kPeriod) < best_pi)
          best_pi = std::abs(s.t - 2.5 * kPeriod), at_pi = s.a[slider_x];
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  const double ideal_0 = -kCrank * kOmega * kOmega * (1.0 + kCrank / kRod);
  const double ideal_pi = kCrank * kOmega * kOmega * (1.0 - kCrank / kRod);
  const double kinetic = 0.5 * 0.21 * std::pow(0.5 * kCrank * kOmega, 2);
  std::printf(
      "ideal slider-crank, %s guide: slider acceleration %.2f m/s² at θ = 0 (exact %.2f, error "
      "%.2e), "
      "%.2f at θ = π (exact %.2f, error %.2e); largest |g| %.2e m; energy balance moved "
      "%.2e J (rod's kinetic energy at θ = 0: %.3f J)\n",
      label, at_0, ideal_0, at_0 / ideal_0 - 1.0, at_pi, ideal_pi, at_pi / ideal_pi - 1.0,
      result.statistics.max_constraint_violation,
      last_energy.Balance() - first_energy.Balance(), kinetic);
  EXPECT_NEAR(at_0 / ideal_0, 1.0, 1e-3);
  EXPECT_NEAR(at_pi / ideal_pi, 1.0, 1e-3);
  // Newton's tolerance at the pins, 0.05 to 0.17 m from the origin: atol + rtol |c|.
  EXPECT_LT(result.statistics.max_constraint_violation, 1e-12 + 1e-10 * (kCrank + kRod));
  EXPECT_LT(std::abs(last_energy.Balance() - first_energy.Balance()), 1e-2 * kinetic);
}

TEST(IdealJoints, SliderCrankSliderAccelerationMatchesTheKinematics) {
  ExpectSliderAccelerationAsTheKinematics(IdealJoint::Type::kLine, "line");
  ExpectSliderAccelerationAsTheKinematics(IdealJoint::Type::kPrismatic, "prismatic");
}

TEST(IdealJoints, BlockOnAPrismaticJointSlidesDownTheIncline) {
  // A turned, spinning block on a prismatic joint to the ground along a = (cos 30°, 0, −sin 30°),
  // under gravity −z: its velocities are projected onto the joint (the spin and the velocity
  // across the guide vanish), it slides with g sin 30° and keeps its orientation:
  // s(t) = (v₀·a) t + ½ g sin 30° t².
  const Vector3d axis(std::cos(kPi / 6), 0.0, -std::sin(kPi / 6));
  const Vector3d velocity(0.4, 0.3, -0.2);
  const Matrix3d orientation(Eigen::AngleAxisd(0.7, Vector3d(1, -1, 2).normalized()));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  builder.AddRigidBody({.name = "block",
                        .mass = 1.5,
                        .inertia = Vector3d(0.01, 0.02, 0.025).asDiagonal(),
                        .position = Vector3d(0.3, -0.2, 1.0),
                        .orientation = orientation,
                        .velocity = velocity,
                        .angular_velocity = Vector3d(1.0, 2.0, 3.0)});
  builder.AddIdealJoint({.name = "guide",
                         .type = IdealJoint::Type::kPrismatic,
                         .first = {.kind = JointAnchor::Kind::kBody, .name = "block"},
                         .second = {.kind = JointAnchor::Kind::kGround},
                         .axis = axis});
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 1e-2;
  settings.end_time = 1.0;
  State state = MakeInitialState(model);
  const SolveResult result =
      SolveDynamic(model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  const double t = settings.end_time;
  const Vector3d expected = Vector3d(0.3, -0.2, 1.0) +
                            (velocity.dot(axis) * t + 0.5 * kGravity * std::sin(kPi / 6) * t * t) *
                                axis;
  const BodyPose pose = CalcBodyPose(model, state, 0);
  std::printf("block on the incline at t = 1 s: position error %.2e m, turned by %.2e rad, "
              "largest |g| %.2e\n",
              (pose.p_WB - expected).norm(),
              Eigen::AngleAxisd(pose.R_WB * orientation.transpose()).angle(),
              result.statistics.max_constraint_violation);
  EXPECT_LT((pose.p_WB - expected).norm(), 1e-8);
  EXPECT_LT(Eigen::AngleAxisd(pose.R_WB * orientation.transpose()).angle(), 1e-8);
  EXPECT_LT(result.statistics.max_constraint_violation, 1e-8);
}

// ---- Statics --------------------------------------------------------------------------------

TEST(IdealJoints, CablePinnedToTheGroundAndABodyCarriesItsLoadThroughTheJoints) {
  // A 1 m nylon rope (d = 4 mm) along x, pinned by spherical joints to the ground at its start
  // and to a fixed body at its end, under gravity (−z) and a load F at its middle. By symmetry
  // each joint carries half of the weight and of F; the horizontal reactions (the rope's
  // tension) are equal and opposite.
  const Material nylon{.youngs_modulus = 3e9, .density = 1140};
  const Section section = MakeCircleSection(0.004);
  const Vector3d load(0.0, 0.3, -2.0);  // N
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  builder.AddCable({.name = "rope",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0, 0),
                    .num_elements = 8,
                    .properties = MakeCableProperties(nylon, section)});
  builder.AddRigidBody({.name = "bracket",
                        .mass = 1.0,
                        .position = Vector3d(1.05, 0, 0),
                        .motion = BodyMotion::kFixed});
  builder.AddPointForce({"rope", 0.5}, load);
  using Kind = JointAnchor::Kind;
  builder.AddIdealJoint({.name = "wall_pin",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = Kind::kPoint, .name = "rope", .s = 0.0},
                         .second = {.kind = Kind::kGround}});
  builder.AddIdealJoint({.name = "bracket_pin",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = Kind::kPoint, .name = "rope", .s = 1.0},
                         .second = {.kind = Kind::kBody, .name = "bracket"}});
  const Model model = builder.Build();
  StaticSettings settings;
  settings.load_steps = 4;
  State state = MakeInitialState(model);
  const SolveResult result =
      SolveStatic(model, settings, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  // g = c_rope − c_other: the joint pushes the rope with −λ.
  const Vector3d on_start = -state.multipliers.segment<3>(0);
  const Vector3d on_end = -state.multipliers.segment<3>(3);
  const double weight = nylon.density * section.area * 1.0 * kGravity;
  const Vector3d expected_each = 0.5 * (Vector3d(0, 0, weight) - load);
  const Vector3d end_position = state.q.segment<3>(model.NodePositionDof(8));
  std::printf(
      "pinned rope: reactions (%.6f, %.6f, %.6f) N and (%.6f, %.6f, %.6f) N, expected vertical "
      "and lateral (%.6f, %.6f) N each; end moved %.2e m; largest |g| %.2e m\n",
      on_start.x(), on_start.y(), on_start.z(), on_end.x(), on_end.y(), on_end.z(),
      expected_each.y(), expected_each.z(), (end_position - Vector3d(1, 0, 0)).norm(),
      result.statistics.max_constraint_violation);
  const double scale = expected_each.norm();
  EXPECT_NEAR(on_start.y(), expected_each.y(), 1e-6 * scale);
  EXPECT_NEAR(on_start.z(), expected_each.z(), 1e-6 * scale);
  EXPECT_NEAR(on_end.y(), expected_each.y(), 1e-6 * scale);
  EXPECT_NEAR(on_end.z(), expected_each.z(), 1e-6 * scale);
  EXPECT_NEAR(on_start.x() + on_end.x(), 0.0, 1e-6 * scale);
  EXPECT_LT(on_start.x(), 0.0);  // the sagging rope is in tension: held outwards at both ends
  EXPECT_LT((end_position - Vector3d(1, 0, 0)).norm(), 1e-8);
}

// ---- Joints on cable points against the builder's own supports ------------------------------

// A 1 m steel strip along x (20 × 5 mm), 8 elements.
void AddStrip(ModelBuilder* builder) {
  const Material steel{.youngs_modulus = 2.0e11, .density = 7800.0};
  builder->AddCable({.name = "strip",
                     .start = Vector3d::Zero(),
                     .end = Vector3d(1.0, 0, 0),
                     .num_elements = 8,
                     .properties = MakeCableProperties(steel, MakeRectangleSection(0.02, 0.005))});
}

// A fixed body "wall", turned and off the strip, and the strip's start welded to it.
void AddWallAndWeld(ModelBuilder* builder) {
  builder->AddRigidBody(
      {.name = "wall",
       .mass = 1.0,
       .position = Vector3d(-0.1, 0.02, 0),
       .orientation = Matrix3d(Eigen::AngleAxisd(0.3, Vector3d(1, 2, 3).normalized())),
       .motion = BodyMotion::kFixed});
  builder->AddIdealJoint({.name = "weld",
                          .type = IdealJoint::Type::kWeld,
                          .first = {.kind = JointAnchor::Kind::kPoint, .name = "strip", .s = 0.0},
                          .second = {.kind = JointAnchor::Kind::kBody, .name = "wall"}});
}

Vector3d TipPosition(const Model& model, const State& state) {
  return state.q.segment<3>(model.NodePositionDof(model.cables()[0].first_node + 8));
}

TEST(IdealJoints, CableWeldedToAFixedBodyBendsAsAClampedCantilever) {
  // The weld holds the strip's end and slope where the body holds them: the same equilibrium as
  // the builder's clamp, under a tip load large enough to bend it far (tip rotation ≈ 0.5 rad).
  const Vector3d load(0.0, -150.0, 40.0);
  StaticSettings settings;
  settings.load_steps = 4;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-12;
  ModelBuilder clamped;
  AddStrip(&clamped);
  clamped.AddClamp({"strip", 0.0});
  clamped.AddPointForce({"strip", 1.0}, load);
  const Model clamped_model = clamped.Build();
  ModelBuilder welded;
  AddStrip(&welded);
  AddWallAndWeld(&welded);
  welded.AddPointForce({"strip", 1.0}, load);
  const Model welded_model = welded.Build();
  const auto no_output = [](const State&, const EnergyAccount&) {};
  State clamped_state = MakeInitialState(clamped_model);
  ASSERT_TRUE(SolveStatic(clamped_model, settings, no_output, &clamped_state).completed);
  State welded_state = MakeInitialState(welded_model);
  const SolveResult result = SolveStatic(welded_model, settings, no_output, &welded_state);
  ASSERT_TRUE(result.completed) << result.message;
  const Vector3d clamped_tip = TipPosition(clamped_model, clamped_state);
  const Vector3d welded_tip = TipPosition(welded_model, welded_state);
  // The weld's reaction on the wall carries the whole load and its moment about the weld.
  JointConstraints constraints(welded_model);
  constraints.Evaluate(welded_state.q, welded_state.v, welded_state.body_rotation);
  const JointReaction reaction = constraints.CalcReaction(0, welded_state.multipliers);
  const Vector3d& on_wall = reaction.force;
  const Vector3d load_moment = welded_tip.cross(load);  // about the weld at the origin
  std::printf(
      "welded strip: tip (%.9f, %.9f, %.9f) m, clamped (%.9f, %.9f, %.9f) m; force on the "
      "wall (%.6f, %.6f, %.6f) N, moment (%.6f, %.6f, %.6f) N m (the load's: (%.6f, %.6f, "
      "%.6f))\n",
      welded_tip.x(), welded_tip.y(), welded_tip.z(), clamped_tip.x(), clamped_tip.y(),
      clamped_tip.z(), on_wall.x(), on_wall.y(), on_wall.z(), reaction.moment.x(),
      reaction.moment.y(), reaction.moment.z(), load_moment.x(), load_moment.y(),
      load_moment.z());
  EXPECT_GT((clamped_tip - Vector3d(1, 0, 0)).norm(), 0.3);  // a large deflection
  EXPECT_LT((welded_tip - clamped_tip).norm(), 1e-9);
  EXPECT_LT((on_wall - load).norm(), 1e-8 * load.norm());
  EXPECT_LT((reaction.moment - load_moment).norm(), 1e-8 * load_moment.norm());
}

TEST(IdealJoints, CablePendulumOnASphericalJointSwingsAsOnTheBuildersPin) {
  // The strip released horizontally under gravity, its start held by a spherical joint to the
  // ground or by the builder's pin (its position coordinates fixed): the same motion.
  DynamicSettings settings;
  settings.time_step = 1e-3;
  settings.end_time = 0.3;
  settings.newton.relative_tolerance = 1e-10;
  settings.newton.absolute_tolerance = 1e-12;
  ModelBuilder pinned;
  pinned.SetGravity(Vector3d(0, 0, -kGravity));
  AddStrip(&pinned);
  pinned.AddPin({"strip", 0.0});
  const Model pinned_model = pinned.Build();
  ModelBuilder jointed;
  jointed.SetGravity(Vector3d(0, 0, -kGravity));
  AddStrip(&jointed);
  jointed.AddIdealJoint({.name = "pin",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = JointAnchor::Kind::kGround},
                         .second = {.kind = JointAnchor::Kind::kPoint, .name = "strip", .s = 0.0}});
  const Model jointed_model = jointed.Build();
  const auto no_output = [](const State&, const EnergyAccount&) {};
  State pinned_state = MakeInitialState(pinned_model);
  ASSERT_TRUE(SolveDynamic(pinned_model, settings, 0.0, no_output, &pinned_state).completed);
  State jointed_state = MakeInitialState(jointed_model);
  const SolveResult result =
      SolveDynamic(jointed_model, settings, 0.0, no_output, &jointed_state);
  ASSERT_TRUE(result.completed) << result.message;
  const Vector3d pinned_tip = TipPosition(pinned_model, pinned_state);
  const Vector3d jointed_tip = TipPosition(jointed_model, jointed_state);
  std::printf("cable pendulum at t = 0.3 s: tip (%.9f, %.9f, %.9f) m on the joint, "
              "(%.9f, %.9f, %.9f) m on the pin; largest |g| %.2e m\n",
              jointed_tip.x(), jointed_tip.y(), jointed_tip.z(), pinned_tip.x(), pinned_tip.y(),
              pinned_tip.z(), result.statistics.max_constraint_violation);
  EXPECT_LT(pinned_tip.z(), -0.3);  // it has swung down
  EXPECT_LT((jointed_tip - pinned_tip).norm(), 1e-7);
  EXPECT_LT(result.statistics.max_constraint_violation, 1e-12);
}

TEST(IdealJoints, ModesOfStripsHeldByJointsAreThoseOfTheBuildersSupports) {
  // Modal analysis restricted to what the joints allow: a strip welded to a fixed body has the
  // modes of the clamped cantilever, one held by spherical joints at both ends (to the ground and
  // to a fixed body) those of the strip on the builder's pins.
  const auto frequencies = [](const Model& model) {
    const ModalResult modes =
        CalcModes(model, MakeInitialState(model).q, ModalSettings{.num_modes = 6});
    EXPECT_TRUE(modes.converged) << modes.message;
    return VectorXd(modes.frequency_hz);
  };
  ModelBuilder clamped;
  AddStrip(&clamped);
  clamped.AddClamp({"strip", 0.0});
  ModelBuilder welded;
  AddStrip(&welded);
  AddWallAndWeld(&welded);
  ModelBuilder pinned;
  AddStrip(&pinned);
  pinned.AddPin({"strip", 0.0});
  pinned.AddPin({"strip", 1.0});
  ModelBuilder jointed;
  AddStrip(&jointed);
  jointed.AddRigidBody({.name = "bracket",
                        .mass = 1.0,
                        .position = Vector3d(1.05, 0, 0),
                        .motion = BodyMotion::kFixed});
  jointed.AddIdealJoint({.name = "start",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = JointAnchor::Kind::kPoint, .name = "strip", .s = 0.0},
                         .second = {.kind = JointAnchor::Kind::kGround}});
  jointed.AddIdealJoint({.name = "end",
                         .type = IdealJoint::Type::kSpherical,
                         .first = {.kind = JointAnchor::Kind::kPoint, .name = "strip", .s = 1.0},
                         .second = {.kind = JointAnchor::Kind::kBody, .name = "bracket"}});
  const VectorXd clamped_f = frequencies(clamped.Build());
  const VectorXd welded_f = frequencies(welded.Build());
  const VectorXd pinned_f = frequencies(pinned.Build());
  const VectorXd jointed_f = frequencies(jointed.Build());
  std::printf("modes (Hz): welded %.6f %.6f %.6f, clamped %.6f %.6f %.6f; jointed %.6f %.6f %.6f, "
              "pinned %.6f %.6f %.6f\n",
              welded_f[0], welded_f[2], welded_f[4], clamped_f[0], clamped_f[2], clamped_f[4],
              jointed_f[0], jointed_f[2], jointed_f[4], pinned_f[0], pinned_f[2], pinned_f[4]);
  // The first bending mode of the clamped strip, 1.8751² √(EI/ρA)/(2π L²) = 4.090 Hz (the cable
  // element bends isotropically with the strip's I = w h³/12: modes come in pairs).
  const double ei = 2e11 * 0.02 * std::pow(0.005, 3) / 12.0;
  const double rho_a = 7800.0 * 0.02 * 0.005;
  EXPECT_NEAR(clamped_f[0], 1.8751 * 1.8751 / (2.0 * kPi) * std::sqrt(ei / rho_a), 1e-3);
  EXPECT_LT((welded_f - clamped_f).cwiseAbs().maxCoeff(), 1e-7 * clamped_f.maxCoeff());
  EXPECT_LT((jointed_f - pinned_f).cwiseAbs().maxCoeff(), 1e-7 * pinned_f.maxCoeff());
}

TEST(IdealJoints, BodyOnARevoluteJointAboutTheCableTangentSpinsFreely) {
  // A flag (a body) on a revolute joint at the tip of a clamped strip, its axis the strip's
  // tangent, no gravity. Spun about the tangent, it spins on at the same rate and the strip stays
  // straight (the joint passes no moment about its axis); given a wobble as well, the joint ties
  // the flag's other rotations to the strip's slope, |g| stays at Newton's tolerance and the
  // energy balance holds.
  const auto run = [](const Vector3d& spin, double* max_drift, double* tip_offset,
                      Vector3d* final_spin) {
    ModelBuilder builder;
    AddStrip(&builder);
    builder.AddClamp({"strip", 0.0});
    builder.AddRigidBody({.name = "flag",
                          .mass = 0.5,
                          .inertia = Vector3d(2e-4, 1e-3, 1e-3).asDiagonal(),
                          .position = Vector3d(1.0, 0, 0),
                          .angular_velocity = spin});
    builder.AddIdealJoint({.name = "hinge",
                           .type = IdealJoint::Type::kRevolute,
                           .first = {.kind = JointAnchor::Kind::kPoint, .name = "strip", .s = 1.0},
                           .second = {.kind = JointAnchor::Kind::kBody, .name = "flag"},
                           .axis = Vector3d::UnitX()});
    const Model model = builder.Build();
    DynamicSettings settings;
    settings.time_step = 5e-4;
    settings.end_time = 0.2;
    settings.spectral_radius = 0.95;
    settings.newton.relative_tolerance = 1e-10;
    settings.newton.absolute_tolerance = 1e-12;
    State state = MakeInitialState(model);
    double e0 = 0.0, kinetic0 = 0.0;
    bool first = true;
    *max_drift = 0.0;
    const SolveResult result = SolveDynamic(
        model, settings, 0.0,
        [&](const State&, const EnergyAccount& energy) {
          if (first) e0 = energy.Balance(), kinetic0 = energy.kinetic, first = false;
          *max_drift = std::max(*max_drift, std::abs(energy.Balance() - e0) / kinetic0);
        },
        &state);
    EXPECT_TRUE(result.completed) << result.message;
    EXPECT_LT(result.statistics.max_constraint_violation, 1e-11);
    *tip_offset = (TipPosition(model, state) - Vector3d(1, 0, 0)).norm();
    *final_spin = state.v.segment<3>(model.rigid_bodies()[0].rotation_dof());
  };
  double drift = 0.0, offset = 0.0;
  Vector3d spin;
  run(Vector3d(20.0, 0, 0), &drift, &offset, &spin);
  std::printf("flag spun about the tangent: spin (%.9f, %.2e, %.2e) rad/s after 0.2 s, tip moved "
              "%.2e m, energy drift %.2e\n",
              spin.x(), spin.y(), spin.z(), offset, drift);
  EXPECT_NEAR(spin.x(), 20.0, 1e-9);
  EXPECT_LT(spin.tail<2>().norm(), 1e-9);
  EXPECT_LT(offset, 1e-12);
  run(Vector3d(20.0, 0, 3.0), &drift, &offset, &spin);
  std::printf("flag with a wobble: tip moved %.3e m, energy drift %.2e of the initial kinetic "
              "energy\n",
              offset, drift);
  EXPECT_GT(offset, 1e-5);  // the wobble bends the strip (0.11 mm)
  EXPECT_LT(drift, 1e-2);
}

}  // namespace
}  // namespace ancfnet
