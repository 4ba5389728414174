// The time loop allocates nothing: after the first step (which sizes the workspaces and factorises
// the iteration matrix), steps of either integrator, Jacobian refreshes, changes of step size and
// the energy accounting must not reach the heap. Every heap request of the process is counted by
// interposing glibc's malloc family, which Eigen, KLU and operator new all end in.

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <memory>

#include "../verification/verification_scenes.hpp"
#include "ancfnet/analysis/energy_tracker.hpp"
#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/forces/self_contact.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/explicit_verlet.hpp"
#include "ancfnet/integrators/generalized_alpha.hpp"
#include "ancfnet/integrators/implicit_midpoint.hpp"

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
void Count() {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
}
}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  Count();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  Count();
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  Count();
  return __libc_realloc(pointer, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  Count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** pointer, std::size_t alignment, std::size_t size) {
  Count();
  *pointer = __libc_memalign(alignment, size);
  return *pointer ? 0 : ENOMEM;
}
}

namespace ancfnet {
namespace {

// Heap requests made while `body` runs.
template <class Body>
long CountAllocations(Body body) {
  allocations = 0;
  counting = true;
  body();
  counting = false;
  return allocations.load();
}

TEST(TimeLoopAllocation, CounterSeesHeapRequests) {
  // Guards the test itself: were the interposition lost, every other case would pass vacuously.
  const long count = CountAllocations([] {
    VectorXd v(1000);
    v.setOnes();
    EXPECT_EQ(v.sum(), 1000.0);
  });
  EXPECT_GE(count, 1);
}

// Damped pendulum (Kelvin–Voigt on) so that viscous forces and their Jacobian are exercised;
// 128 elements so that force assembly runs its OpenMP loop.
void ExpectGeneralizedAlphaLoopAllocatesNothing(JacobianUpdate update, int elements) {
  const Model model = verification::MakePendulum(elements, 1e-3);
  DynamicSettings settings;
  settings.jacobian_update = update;
  GeneralizedAlphaIntegrator integrator(model, settings);
  State state = MakeInitialState(model);
  ASSERT_TRUE(integrator.Initialize(&state));
  EnergyTracker energy(model, integrator.workspace(), state, 1.0,
                       GeneralizedAlphaIntegrator::kEnergyQuadrature);
  ASSERT_TRUE(integrator.Step(1e-3, &state).accepted);  // warm-up: sizes and first factorisation

  int rejected = 0;
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) {
      const double h = i % 10 < 5 ? 1e-3 : 5e-4;  // step-size changes force refactorisations
      const StepOutcome outcome = integrator.Step(h, &state);
      if (!outcome.accepted) ++rejected;
      energy.Advance(model, integrator.workspace(), state, 1.0);
    }
  });
  EXPECT_EQ(rejected, 0);
  EXPECT_EQ(count, 0) << "heap requests in 40 generalised-α steps";
}

TEST(TimeLoopAllocation, GeneralizedAlphaWithAdaptiveJacobian) {
  ExpectGeneralizedAlphaLoopAllocatesNothing(JacobianUpdate::kAdaptive, 8);
}

TEST(TimeLoopAllocation, GeneralizedAlphaWithFullNewtonAndOpenMp) {
  ExpectGeneralizedAlphaLoopAllocatesNothing(JacobianUpdate::kEveryIteration, 128);
}

// The midpoint rule with Rayleigh and modal damping (their forces and the Rayleigh Jacobian every
// step).
TEST(TimeLoopAllocation, ImplicitMidpointWithRayleighAndModalDamping) {
  ModelBuilder builder = verification::MakeCantilever(8);
  builder.SetRayleighDamping({.alpha = 0.1, .beta = 1e-5});
  ModalDamping modal;
  modal.num_modes = 4;
  modal.ratios = {0.01, 0.01, 0.02, 0.02};
  builder.SetModalDamping(modal);
  const Model model = builder.Build();
  DynamicSettings settings;
  ImplicitMidpointIntegrator integrator(model, settings);
  State state = MakeInitialState(model);
  state.v.setConstant(1e-3);
  ASSERT_TRUE(integrator.Initialize(&state));
  EnergyTracker energy(model, integrator.workspace(), state, 1.0,
                       ImplicitMidpointIntegrator::kEnergyQuadrature);
  ASSERT_TRUE(integrator.Step(1e-4, &state).accepted);
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) {
      EXPECT_TRUE(integrator.Step(i % 10 < 5 ? 1e-4 : 5e-5, &state).accepted);
      energy.Advance(model, integrator.workspace(), state, 1.0);
    }
  });
  EXPECT_EQ(count, 0) << "heap requests in 40 midpoint steps with damping models";
}

// A pendulum of ANCF beam elements with Kelvin–Voigt damping (issue 13): the beam kernel's force,
// viscous force, stiffness and damping matrix every iteration.
TEST(TimeLoopAllocation, GeneralizedAlphaWithDampedBeams) {
  const double tau = 1e-3;
  CableProperties drawn;
  drawn.axial_damping_time = drawn.bending_damping_time = tau;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "pendulum",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 8,
                    .properties = drawn,
                    .beam = BeamCableSpec{.material = {.youngs_modulus = 2e9,
                                                       .poisson_ratio = 0.3,
                                                       .density = 1000.0,
                                                       .axial_damping_time = tau,
                                                       .bending_damping_time = tau},
                                          .section = MakeCircleBeamSection(0.01, 0.3),
                                          .orientation = Vector3d::UnitZ()}});
  builder.AddPin({"pendulum", 0.0});
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.jacobian_update = JacobianUpdate::kEveryIteration;
  GeneralizedAlphaIntegrator integrator(model, settings);
  State state = MakeInitialState(model);
  ASSERT_TRUE(integrator.Initialize(&state));
  EnergyTracker energy(model, integrator.workspace(), state, 1.0,
                       GeneralizedAlphaIntegrator::kEnergyQuadrature);
  ASSERT_TRUE(integrator.Step(1e-3, &state).accepted);
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) {
      EXPECT_TRUE(integrator.Step(i % 10 < 5 ? 1e-3 : 5e-4, &state).accepted);
      energy.Advance(model, integrator.workspace(), state, 1.0);
    }
  });
  EXPECT_EQ(count, 0) << "heap requests in 40 generalised-α steps of damped beams";
}

// A spinning free body with the flexible pendulum's cable tied to it (gyroscopic term,
// attachment forces and Jacobians, the rotation rebase every step).
template <class Integrator>
long CountBodyLoopAllocations() {
  const CableProperties cord{
      .axial_stiffness = 1e5, .bending_stiffness = 1e-2, .mass_per_length = 0.1};
  ModelBuilder builder;
  builder.AddRigidBody({.name = "target",
                        .mass = 10.0,
                        .inertia = Vector3d(1.0, 2.0, 2.5).asDiagonal(),
                        .angular_velocity = Vector3d(0.1, 2.0, 0.1)});
  builder.AddCable({.name = "cord",
                    .start = Vector3d(0.5, 0.0, 0.0),
                    .end = Vector3d(2.5, 0.0, 0.0),
                    .num_elements = 4,
                    .properties = cord});
  builder.AddBodyAttachment(
      {.name = "hook", .body = "target", .point = {"cord", 0.0}, .stiffness = 1e4, .damping = 1.0});
  const Model model = builder.Build();
  Integrator integrator(model, DynamicSettings{});
  State state = MakeInitialState(model);
  EXPECT_TRUE(integrator.Initialize(&state));
  EnergyTracker energy(model, integrator.workspace(), state, 1.0, Integrator::kEnergyQuadrature);
  EXPECT_TRUE(integrator.Step(1e-3, &state).accepted);
  return CountAllocations([&] {
    for (int i = 0; i < 40; ++i) {
      EXPECT_TRUE(integrator.Step(i % 10 < 5 ? 1e-3 : 5e-4, &state).accepted);
      energy.Advance(model, integrator.workspace(), state, 1.0);
    }
  });
}

TEST(TimeLoopAllocation, RigidBodyWithAttachedCable) {
  EXPECT_EQ(CountBodyLoopAllocations<GeneralizedAlphaIntegrator>(), 0)
      << "heap requests in 40 generalised-α steps with a body";
  EXPECT_EQ(CountBodyLoopAllocations<ImplicitMidpointIntegrator>(), 0)
      << "heap requests in 40 midpoint steps with a body";
}

// A rope pressed onto a faceted sphere (a triangle-mesh target): the bounding-volume hierarchy's
// query, run for every inspection sphere in every Newton iteration, allocates nothing.
TEST(TimeLoopAllocation, GeneralizedAlphaWithMeshContact) {
  // 1280 triangles, its top at z = 0.
  TriangleMesh mesh = MakeIcosphere(1.0, 3);
  TransformTriangleMesh(1.0, Matrix3d::Identity(), Vector3d(0, 0, -1.0), &mesh);
  const auto sphere = std::make_shared<const MeshBvh>(std::move(mesh));
  // The rope (radius 2 mm) at height z across it.
  const auto make_model = [&](double z) {
    ModelBuilder builder;
    builder.SetGravity(Vector3d(0, 0, -9.81));
    builder.AddCable({.name = "rope",
                      .start = Vector3d(-0.4, 0.1, z),
                      .end = Vector3d(0.4, -0.1, z),
                      .num_elements = 4,
                      .properties = MakeCableProperties({.youngs_modulus = 3e9, .density = 1140},
                                                        MakeCircleSection(0.002))});
    ContactSpec spec;
    spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.3);
    ContactTarget target;
    target.kind = ContactTarget::Kind::kMesh;
    target.mesh = sphere;
    spec.targets.push_back(target);
    builder.SetContact(spec);
    return builder.Build();
  };
  // Raised from deep inside until its deepest inspection sphere starts 10 µm into the facets
  // (the facets' vertices stand millimetres above their middles).
  const auto deepest = [](const Model& m) {
    const State start = MakeInitialState(m);
    return TargetContact(m).Summarize(start.q, start.v, start.contact_history).max_penetration;
  };
  double z = -0.005;
  for (int i = 0; i < 4; ++i) z += deepest(make_model(z)) - 1e-5;
  const Model model = make_model(z);
  ASSERT_NEAR(deepest(model), 1e-5, 1e-7);
  DynamicSettings settings;
  GeneralizedAlphaIntegrator integrator(model, settings);
  State state = MakeInitialState(model);
  ASSERT_TRUE(integrator.Initialize(&state));
  ASSERT_TRUE(integrator.Step(1e-4, &state).accepted);
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) EXPECT_TRUE(integrator.Step(1e-4, &state).accepted);
  });
  const TargetContact contact(model);
  EXPECT_GT(contact.Summarize(state.q, state.v, state.contact_history).active, 0);
  EXPECT_EQ(count, 0) << "heap requests in 40 generalised-α steps with mesh contact";
}

// A slack thread draped by gravity across a taut one, both pinned, with self-contact: once the
// contact couplings of the crossing are in the pattern (the warm-up steps), the steps search for
// pairs, evaluate them and keep the pattern without reaching the heap.
TEST(TimeLoopAllocation, GeneralizedAlphaWithSelfContact) {
  constexpr double kRadius = 0.001;
  CableProperties p =
      MakeCableProperties({.youngs_modulus = 3e9, .density = 1140, .axial_damping_time = 1e-4},
                          MakeCircleSection(2 * kRadius));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -9.81));
  builder.AddCable({.name = "a",
                    .start = Vector3d(-0.5, 0, 0),
                    .end = Vector3d(0.5, 0, 0),
                    .num_elements = 9,
                    .properties = p,
                    .natural_length = 0.999});
  builder.AddCable({.name = "b",
                    .start = Vector3d(0, -0.5, 2 * kRadius - 1e-5),
                    .end = Vector3d(0, 0.5, 2 * kRadius - 1e-5),
                    .num_elements = 9,
                    .properties = p});
  for (const char* cable : {"a", "b"}) {
    builder.AddPin({cable, 0.0});
    builder.AddPin({cable, 1.0});
  }
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.5);
  spec.self_contact = true;
  builder.SetContact(spec);
  const Model model = builder.Build();
  GeneralizedAlphaIntegrator integrator(model, DynamicSettings{});
  State state = MakeInitialState(model);
  ASSERT_TRUE(integrator.Initialize(&state));
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(integrator.Step(1e-4, &state).accepted);
  int rebuilds = 0;
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) {
      const StepOutcome outcome = integrator.Step(1e-4, &state);
      EXPECT_TRUE(outcome.accepted);
      rebuilds += outcome.pattern_rebuilds;
    }
  });
  SelfContact watch(model);
  watch.FindCandidates(state, 0.0);
  EXPECT_GT(watch.Summarize(state.q, state.v).active, 0);
  EXPECT_EQ(rebuilds, 0);
  EXPECT_EQ(count, 0) << "heap requests in 40 generalised-α steps with self-contact";
}

TEST(TimeLoopAllocation, ExplicitVerlet) {
  const Model model = verification::MakePendulum(8);
  ExplicitVerletIntegrator integrator(model);
  State state = MakeInitialState(model);
  ASSERT_TRUE(integrator.Initialize(&state));
  const double h = 0.9 * integrator.EstimateCriticalStep(state.q);
  ASSERT_TRUE(integrator.Step(h, &state).accepted);
  const long count = CountAllocations([&] {
    for (int i = 0; i < 40; ++i) EXPECT_TRUE(integrator.Step(h, &state).accepted);
  });
  EXPECT_EQ(count, 0) << "heap requests in 40 Verlet steps";
}

}  // namespace
}  // namespace ancfnet
