// The LuGre (bristle) friction law in contact, through the full solver (generalised-α) with a
// plane target. A block (a point-mass sphere) on a plane tilted by θ: below the friction angle,
// tan θ < μ_s, it pre-slides by the bristle's x = −(μ_s/σ₀) ln(1 − tan θ/μ_s) and stops (the
// quasi-static solution of ż = ẋ (1 − σ₀ z/μ_s) up to σ₀ z = tan θ), while the tanh law creeps
// on at the speed where μ_s tanh(v/v_r) = tan θ; above it, the block slides at
// a = g (sin θ − μ_k cos θ). A thread lying on a horizontal plane, pulled along itself at one
// end by a force F: below μ_s W (its weight W) it pre-slides by the same law with F/W for
// tan θ and stays put; above, it slides at (F − μ_k W)/m. A knot resting on a fixed knot off
// its top sticks like the block (self-contact), and so does a block on a turntable (a plane on a
// turning body), its bristle turning with the table. docs/validation.md, "The LuGre law in
// contact".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

constexpr double kG = 9.81;
constexpr double kMuS = 0.4, kMuK = 0.3;
constexpr double kSigma0 = 1e4;  // 1/m
// Bristle damping near critical for the bristle oscillation at ω = √(σ₀ g): ζ = σ₁ √g/(2 √σ₀).
constexpr double kSigma1 = 60.0;  // s/m
// A Stribeck speed well above the pre-sliding speeds (mm/s), so g(v) ≈ μ_s while sticking.
constexpr double kStribeckSpeed = 0.1;

FrictionLaw LuGre() { return MakeLuGreFriction(kMuS, kMuK, kStribeckSpeed, kSigma0, kSigma1, 0.0); }

// The pre-sliding displacement at the load ratio F/(μ_s N) = r.
double PreSliding(double load_ratio) { return -(kMuS / kSigma0) * std::log(1.0 - load_ratio); }

ContactSpec PlaneContact(const Vector3d& normal, const NormalLaw& law,
                         const FrictionLaw& friction) {
  return verification::MakePlaneContact(law, normal, friction);
}

struct Slide {
  double displacement = 0.0;  // down the slope after `duration` (m)
  double speed = 0.0;         // down the slope at the end (m/s)
  double speed_half = 0.0;    // down the slope at half the duration (m/s)
  double friction = 0.0;      // up the slope, as the contact records give it at the end (N)
};

// A 0.1 kg sphere of radius 1 cm at rest at its static penetration on the plane through the
// origin tilted by θ about y, gravity along −z, generalised-α with h = 0.1 ms.
Slide SlideBlock(double theta_degrees, const FrictionLaw& friction, double duration) {
  constexpr double kMass = 0.1, kRadius = 0.01, kStiffness = 1e4;
  const double theta = theta_degrees * std::numbers::pi / 180.0;
  const Vector3d normal(-std::sin(theta), 0.0, std::cos(theta));
  const Vector3d down_slope(-std::cos(theta), 0.0, -std::sin(theta));
  ContactSpec spec = PlaneContact(normal, MakeLinearContactLaw(kStiffness, 60.0), friction);
  spec.point_mass_radius = kRadius;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kG));
  const double delta = kMass * kG * std::cos(theta) / kStiffness;
  const Vector3d start = (kRadius - delta) * normal;
  builder.AddPointMass("block", kMass, start);
  builder.SetContact(spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 1e-4;
  settings.end_time = duration;
  State state = MakeInitialState(model);
  Slide slide;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        if (std::abs(s.t - 0.5 * duration) < 0.5 * settings.time_step)
          slide.speed_half = s.v.segment<3>(0).dot(down_slope);
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  slide.displacement = (state.q.segment<3>(0) - start).dot(down_slope);
  slide.speed = state.v.segment<3>(0).dot(down_slope);
  std::vector<ContactPoint> records;
  TargetContact(model).CollectContacts(state.q, state.v, state.contact_history, &records);
  if (!records.empty()) slide.friction = -records[0].friction_force_W.dot(down_slope);
  return slide;
}

TEST(LuGreContact, BlockBelowTheFrictionAnglePreSlidesAndSticks) {
  const double theta = 15.0 * std::numbers::pi / 180.0;  // tan θ = 0.268 < μ_s
  const Slide lugre = SlideBlock(15.0, LuGre(), 1.0);
  const double expected = PreSliding(std::tan(theta) / kMuS);
  std::printf("LuGre block at 15°: x = %.4e m (pre-sliding %.4e m), v = %.2e m/s after 1 s\n",
              lugre.displacement, expected, lugre.speed);
  EXPECT_NEAR(lugre.displacement / expected, 1.0, 0.15);
  EXPECT_LT(std::abs(lugre.speed), 1e-6);
  // At rest the bristle holds the slope load m g sin θ (the records evaluate the stored bristle).
  EXPECT_NEAR(lugre.friction, 0.1 * kG * std::sin(theta), 1e-9);
  // The tanh law (v_r = 1 mm/s) creeps at v = v_r atanh(tan θ/g(v)), g(v) ≈ μ_s.
  constexpr double kRegularization = 1e-3;
  const Slide tanh =
      SlideBlock(15.0, MakeTanhFriction(kMuS, kMuK, kRegularization, kStribeckSpeed), 1.0);
  double creep = kRegularization * std::atanh(std::tan(theta) / kMuS);
  for (int i = 0; i < 20; ++i) {  // fixed point with the Stribeck curve
    const double ratio = creep / kStribeckSpeed;
    const double g = kMuK + (kMuS - kMuK) * std::exp(-ratio * ratio);
    creep = kRegularization * std::atanh(std::tan(theta) / g);
  }
  std::printf("tanh block at 15°: creeps at %.4e m/s (expected %.4e), x = %.3e m after 1 s\n",
              tanh.speed, creep, tanh.displacement);
  EXPECT_NEAR(tanh.speed / creep, 1.0, 0.01);
  EXPECT_GT(tanh.displacement, 1.5 * lugre.displacement);
}

TEST(LuGreContact, BlockAboveTheFrictionAngleSlidesAtTheCoulombRate) {
  const double theta = 30.0 * std::numbers::pi / 180.0;  // tan θ = 0.577 > μ_s
  const Slide slide = SlideBlock(30.0, LuGre(), 1.0);
  const double a = kG * (std::sin(theta) - kMuK * std::cos(theta));
  const double measured = (slide.speed - slide.speed_half) / 0.5;
  std::printf("LuGre block at 30°: a = %.5f m/s² (Coulomb %.5f)\n", measured, a);
  EXPECT_NEAR(measured / a, 1.0, 1e-2);
}

struct Pull {
  double displacement = 0.0;  // of the thread's middle along the pull (m)
  double speed = 0.0;         // mean speed of the nodes along the pull at the end (m/s)
  double speed_half = 0.0;    // at half the pull
  double weight = 0.0, mass = 0.0;
};

// A 1 m nylon thread (2 mm, 5 elements, 4 inspection spheres each) settles for 0.2 s on the plane
// z = 0, then is pulled along +x at its end by F = ratio · μ_s W for `duration`.
Pull PullThread(double load_ratio, double duration) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  const CableProperties p = MakeCableProperties(nylon, MakeCircleSection(0.002));
  const double radius = 0.001;
  const double weight = p.mass_per_length * 1.0 * kG;
  ContactSpec spec = PlaneContact(Vector3d::UnitZ(), MakeLinearContactLaw(100.0, 0.3), LuGre());
  spec.points_per_element = 4;
  const auto make = [&](double force) {
    ModelBuilder builder;
    builder.SetGravity(Vector3d(0, 0, -kG));
    const double height = radius - weight / 20 / 100.0;  // each sphere carries W/20
    builder.AddCable({.name = "thread",
                      .start = Vector3d(0, 0, height),
                      .end = Vector3d(1, 0, height),
                      .num_elements = 5,
                      .properties = p});
    if (force > 0.0) builder.AddPointForce({"thread", 1.0}, Vector3d(force, 0, 0));
    builder.SetContact(spec);
    return builder.Build();
  };
  const Model resting = make(0.0);
  const Model pulled = make(load_ratio * kMuS * weight);
  DynamicSettings settings;
  settings.time_step = 2e-4;
  settings.end_time = 0.2;
  State state = MakeInitialState(resting);
  const auto none = [](const State&, const EnergyAccount&) {};
  SolveResult result = SolveDynamic(resting, settings, 0.0, none, &state);
  EXPECT_TRUE(result.completed) << result.message;
  const auto x_speed = [&](const State& s) {
    double sum = 0.0;
    for (Index node = 0; node < pulled.num_nodes(); ++node)
      sum += s.v[pulled.NodePositionDof(node)];
    return sum / pulled.num_nodes();
  };
  const Index middle = pulled.NodePositionDof(pulled.num_nodes() / 2);
  const double x0 = state.q[middle];
  settings.end_time = 0.2 + duration;
  Pull pull{.weight = weight, .mass = p.mass_per_length};
  result = SolveDynamic(
      pulled, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        if (std::abs(s.t - 0.2 - 0.5 * duration) < 0.5 * settings.time_step)
          pull.speed_half = x_speed(s);
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  pull.displacement = state.q[middle] - x0;
  pull.speed = x_speed(state);
  return pull;
}

TEST(LuGreContact, ThreadPulledBelowStictionStaysAndAboveItSlides) {
  const Pull below = PullThread(0.7, 1.0);
  std::printf("thread pulled at 0.7 μ_s W: x = %.4e m (pre-sliding %.4e m), v = %.2e m/s\n",
              below.displacement, PreSliding(0.7), below.speed);
  EXPECT_NEAR(below.displacement / PreSliding(0.7), 1.0, 0.15);
  EXPECT_LT(std::abs(below.speed), 1e-6);
  const Pull above = PullThread(1.5, 0.5);
  const double a = (1.5 * kMuS - kMuK) * kG;  // (F − μ_k W)/m
  const double measured = (above.speed - above.speed_half) / 0.25;
  std::printf("thread pulled at 1.5 μ_s W: a = %.5f m/s² (Coulomb %.5f)\n", measured, a);
  EXPECT_NEAR(measured / a, 1.0, 2e-2);
}

// Self-contact: a knot (0.1 kg point-mass sphere, r = 1 cm) resting on a fixed knot, 15° off its
// top, is a block on a 15° incline for displacements ≪ r: it pre-slides and sticks, as on the
// plane.
TEST(LuGreContact, KnotRestingOnAKnotSticks) {
  constexpr double kMass = 0.1, kRadius = 0.01, kStiffness = 1e4;
  const double theta = 15.0 * std::numbers::pi / 180.0;
  const Vector3d normal(std::sin(theta), 0.0, std::cos(theta));
  const Vector3d down_slope(std::cos(theta), 0.0, -std::sin(theta));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kG));
  builder.AddPointMass("base", 1.0, Vector3d::Zero());
  builder.FixPointMass("base");
  const double delta = kMass * kG * std::cos(theta) / kStiffness;
  const Vector3d start = (2.0 * kRadius - delta) * normal;
  builder.AddPointMass("knot", kMass, start);
  ContactSpec spec;
  spec.normal = MakeLinearContactLaw(kStiffness, 60.0);
  spec.friction = LuGre();
  spec.point_mass_radius = kRadius;
  spec.self_contact = true;
  builder.SetContact(spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 1e-4;
  settings.end_time = 1.0;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state);
  ASSERT_TRUE(result.completed) << result.message;
  const Index dof = model.point_masses()[1].dof;
  const double x = (state.q.segment<3>(dof) - start).dot(down_slope);
  const double speed = state.v.segment<3>(dof).norm();
  const double expected = PreSliding(std::tan(theta) / kMuS);
  std::printf("LuGre knot on a knot at 15°: x = %.4e m (pre-sliding %.4e m), v = %.2e m/s\n", x,
              expected, speed);
  EXPECT_NEAR(x / expected, 1.0, 0.15);
  EXPECT_LT(speed, 1e-6);
}

// A turntable: a plane carried by a body turning at ω = 2 rad/s about the vertical, and a block at
// R = 0.5 m on it, moving with it from the start. The centripetal load m ω² R = 0.51 μ_s N is held
// by the bristle, which must turn with the table (it is stored in the body's frame): the block
// pre-slides outwards, then stays at one place on the table. A bristle left fixed in space would
// have to be re-stretched by a slip of ω |z| along the rim, 2π |z| ≈ 0.1 mm a turn.
TEST(LuGreContact, BlockOnATurntableTurnsWithIt) {
  constexpr double kMass = 0.1, kRadius = 0.01, kStiffness = 1e4, kOmega = 2.0, kArm = 0.5;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kG));
  builder.AddRigidBody({.name = "table",
                        .mass = 10.0,
                        .angular_velocity = Vector3d(0, 0, kOmega),
                        .motion = BodyMotion::kPrescribed});
  const double delta = kMass * kG / kStiffness;
  builder.AddPointMass("block", kMass, Vector3d(kArm, 0, kRadius - delta),
                       Vector3d(0, kOmega * kArm, 0));
  ContactSpec spec =
      PlaneContact(Vector3d::UnitZ(), MakeLinearContactLaw(kStiffness, 60.0), LuGre());
  spec.targets[0].body_name = "table";
  spec.point_mass_radius = kRadius;
  builder.SetContact(spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 2e-4;
  const double turn = 2.0 * std::numbers::pi / kOmega;
  settings.end_time = 0.5 + turn;
  State state = MakeInitialState(model);
  const Index dof = model.point_masses()[0].dof;
  // The block's place on the table, x_B = Rᵀ(ωt) x.
  const auto on_table = [&](const State& s) {
    return Vector3d(Eigen::AngleAxisd(-kOmega * s.t, Vector3d::UnitZ()) * s.q.segment<3>(dof));
  };
  Vector3d start = Vector3d::Zero();
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        if (std::abs(s.t - 0.5) < 0.5 * settings.time_step) start = on_table(s);
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  const Vector3d end = on_table(state);
  const double outwards = start.x() - kArm;
  const double expected = PreSliding(kOmega * kOmega * kArm / (kMuS * kG));
  std::printf(
      "LuGre turntable: pre-slides %.4e m outwards (1-D value %.4e m), then moves %.2e m "
      "on the table in a turn\n",
      outwards, expected, (end - start).norm());
  EXPECT_NEAR(outwards / expected, 1.0, 0.15);
  EXPECT_LT((end - start).norm(), 1e-6);
}

TEST(LuGreContact, ExplicitIntegratorRefusesTheLaw) {
  ModelBuilder builder;
  builder.AddPointMass("block", 0.1, Vector3d::Zero());
  builder.SetContact(PlaneContact(Vector3d::UnitZ(), MakeLinearContactLaw(1e4, 0.0), LuGre()));
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.integrator = IntegratorType::kExplicitVerlet;
  State state = MakeInitialState(model);
  EXPECT_THROW(SolveDynamic(
                   model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state),
               InputError);
}

}  // namespace
}  // namespace ancfnet
