// A time loop continued from a checkpoint (TimeLoopCheckpoints) reproduces the run that never
// stopped bit for bit: the outputs after the checkpoint, the final state and the statistics. The
// scenes carry every kind of memory a step leaves behind: contact impact speeds, LuGre bristles,
// self-contact pairs, contact couplings of the iteration matrix, the reused Jacobian with its KLU
// pivot order, ā of generalised-α, the energy account and the energy step control.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

// A small net dropped on a sphere with friction; its threads touch each other too.
constexpr const char* kNetDrop = R"(
gravity: [0, 0, -9.81]
materials:
  thread: {youngs_modulus: 1.0e9, density: 1000, axial_damping_time: 1.0e-4}
sections:
  thread: {shape: circle, diameter: 0.002}
nets:
  - {name: net, type: square, side: 0.6, meshes: 4, center: [0, 0, 0.32], material: thread,
     section: thread, knot_model: ideal}
contact:
  law: {type: carvalho_martins, stiffness: 1.0e6, restitution: 0.3}
  friction: {type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-2}
  points_per_element: 4
  point_mass_radius: 0.001
  self_contact: true
  targets:
    - {name: ball, type: sphere, center: [0, 0, 0], radius: 0.3}
analysis: {type: dynamic, spectral_radius: 0.5, time_step: 2.0e-3, end_time: 0.2,
           energy_drift: 0.01}
)";

// A block sliding down a slope with LuGre friction (bristle states).
constexpr const char* kLuGreIncline = R"(
gravity: [0, 0, -9.81]
point_masses:
  - {name: block, mass: 0.1, position: [-0.0025636, 0.0, 0.0095677], velocity: [0.3, 0, 0]}
contact:
  law: {type: linear, stiffness: 1.0e4, damping: 60}
  friction: {type: lugre, static: 0.4, kinetic: 0.3, stribeck_speed: 0.1,
             bristle_stiffness: 1.0e4, bristle_damping: 60}
  point_mass_radius: 0.01
  targets:
    - {name: slope, type: plane, point: [0, 0, 0], normal: [-0.2588190, 0, 0.9659258]}
analysis: {type: dynamic, integrator: INTEGRATOR, time_step: 1.0e-3, end_time: 0.2}
)";

std::string WithIntegrator(std::string text, const std::string& integrator) {
  text.replace(text.find("INTEGRATOR"), 10, integrator);
  return text;
}

struct Output {
  double t;
  VectorXd q, v;
  EnergyAccount energy;
};

bool SameBits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

void ExpectSameOutputs(const std::vector<Output>& expected, const std::vector<Output>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(expected[i].t);
    EXPECT_EQ(expected[i].t, actual[i].t);
    EXPECT_TRUE(SameBits(expected[i].q, actual[i].q));
    EXPECT_TRUE(SameBits(expected[i].v, actual[i].v));
    EXPECT_EQ(expected[i].energy.work, actual[i].energy.work);
    EXPECT_EQ(expected[i].energy.dissipated, actual[i].energy.dissipated);
    EXPECT_EQ(expected[i].energy.kinetic, actual[i].energy.kinetic);
  }
}

// Runs the scene uninterrupted with a checkpoint every `every` s, then from its checkpoint number
// `which` again, and compares; the failures of the uninterrupted run into `failures` when given.
void ExpectRestartReproducesTheRun(const std::string& yaml, double every, std::size_t which,
                                   std::vector<FailureEvent>* failures = nullptr) {
  const Scene scene = ParseScene(yaml);
  const DynamicSettings& settings = scene.analysis.dynamics;
  std::vector<Output> outputs;
  const OutputCallback record = [&](const State& s, const EnergyAccount& e) {
    outputs.push_back({s.t, s.q, s.v, e});
  };
  struct Checkpoint {
    double t;
    std::size_t outputs;
    std::vector<std::byte> bytes;
  };
  std::vector<Checkpoint> checkpoints;
  TimeLoopCheckpoints taking{.every = every};
  taking.write = [&](const State& s, const std::vector<std::byte>& bytes) {
    checkpoints.push_back({s.t, outputs.size(), bytes});
  };
  State state = MakeInitialState(scene.model);
  const SolveResult full = SolveDynamic(scene.model, settings, 0.0, record, &state, taking);
  ASSERT_TRUE(full.completed) << full.message;
  if (failures) *failures = full.failures;
  ASSERT_GT(checkpoints.size(), which);
  const std::vector<Output> full_outputs = outputs;
  const Checkpoint& from = checkpoints[which];
  ASSERT_GT(from.t, 0.0);

  // Without checkpoints the run is the same: taking them changes nothing.
  outputs.clear();
  State plain = MakeInitialState(scene.model);
  SolveDynamic(scene.model, settings, 0.0, record, &plain);
  ExpectSameOutputs(full_outputs, outputs);

  outputs.clear();
  ArchiveReader reader(from.bytes.data(), from.bytes.size(), "checkpoint");
  State resumed = MakeInitialState(scene.model);
  const SolveResult rest = SolveDynamic(scene.model, settings, 0.0, record, &resumed,
                                        {.every = 0.0, .resume = &reader});
  ASSERT_TRUE(rest.completed) << rest.message;
  ExpectSameOutputs({full_outputs.begin() + static_cast<std::ptrdiff_t>(from.outputs),
                     full_outputs.end()},
                    outputs);
  EXPECT_TRUE(SameBits(state.a, resumed.a));
  EXPECT_EQ(full.statistics.steps, rest.statistics.steps);
  EXPECT_EQ(full.statistics.newton_iterations, rest.statistics.newton_iterations);
  EXPECT_EQ(full.statistics.jacobian_updates, rest.statistics.jacobian_updates);
  EXPECT_EQ(full.statistics.step_cuts, rest.statistics.step_cuts);
}

TEST(DynamicSolverCheckpoint, NetOnASphereWithSelfContactContinuesBitForBit) {
  ExpectRestartReproducesTheRun(kNetDrop, 0.03, 3);
}

TEST(DynamicSolverCheckpoint, LuGreBristlesContinueBitForBitWithEveryIntegrator) {
  for (const char* integrator : {"generalized_alpha", "midpoint"}) {
    SCOPED_TRACE(integrator);
    ExpectRestartReproducesTheRun(WithIntegrator(kLuGreIncline, integrator), 0.05, 1);
  }
}

TEST(DynamicSolverCheckpoint, ExplicitVerletContinuesBitForBit) {
  std::string yaml = WithIntegrator(kLuGreIncline, "explicit_verlet");
  yaml.replace(yaml.find("type: lugre, static: 0.4, kinetic: 0.3, stribeck_speed: 0.1,\n"
                         "             bristle_stiffness: 1.0e4, bristle_damping: 60"),
               std::string("type: lugre, static: 0.4, kinetic: 0.3, stribeck_speed: 0.1,\n"
                           "             bristle_stiffness: 1.0e4, bristle_damping: 60")
                   .size(),
               "type: tanh, static: 0.3, kinetic: 0.3, regularization_speed: 1.0e-2");
  yaml.replace(yaml.find("time_step: 1.0e-3"), 17, "time_step: 1.0e-4");
  ExpectRestartReproducesTheRun(yaml, 0.05, 1);
}

// A chain whose top spring breaks early: the time loop initialises the integrator again at the
// failure, and the run continued after it still matches.
TEST(DynamicSolverCheckpoint, ARunContinuedAfterALinkBrokeMatchesWithEveryIntegrator) {
  for (const char* integrator : {"generalized_alpha", "midpoint", "explicit_verlet"}) {
    SCOPED_TRACE(integrator);
    std::vector<FailureEvent> failures;
    ExpectRestartReproducesTheRun(fmt::format(R"(
gravity: [0, 0, -9.81]
point_masses:
  - {{name: anchor, mass: 1.0, position: [0, 0, 0], fixed: true}}
  - {{name: upper, mass: 1.0, position: [0.1, 0, -1]}}
  - {{name: lower, mass: 1.0, position: [0.2, 0, -2]}}
spring_dampers:
  - {{name: top, from: anchor, to: upper, law: {{type: linear, stiffness: 1000}},
     breaking_force: 25}}
  - {{name: bottom, from: upper, to: lower, law: {{type: linear, stiffness: 1000}}}}
analysis: {{type: dynamic, integrator: {}, time_step: 1.0e-4, end_time: 0.3}}
)",
                                              integrator),
                                  0.05, 2, &failures);
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_LT(failures[0].time, 0.15);  // before the checkpoint the run continues from
  }
}

TEST(DynamicSolverCheckpoint, ACheckpointOfAnotherModelIsRefused) {
  const Scene scene = ParseScene(WithIntegrator(kLuGreIncline, "generalized_alpha"));
  std::vector<std::byte> bytes;
  TimeLoopCheckpoints taking{.every = 0.1};
  taking.write = [&](const State&, const std::vector<std::byte>& b) { bytes = b; };
  State state = MakeInitialState(scene.model);
  SolveDynamic(scene.model, scene.analysis.dynamics, 0.0,
               [](const State&, const EnergyAccount&) {}, &state, taking);
  ASSERT_FALSE(bytes.empty());
  const Scene net = ParseScene(kNetDrop);
  ArchiveReader reader(bytes.data(), bytes.size(), "checkpoint.bin");
  State other = MakeInitialState(net.model);
  EXPECT_THROW(SolveDynamic(net.model, net.analysis.dynamics, 0.0,
                            [](const State&, const EnergyAccount&) {}, &other,
                            {.resume = &reader}),
               InputError);
}

}  // namespace
}  // namespace ancfnet
