// The consistent initial acceleration a₀ = M⁻¹ (Q_ext − Q_int) takes its forces from SystemForces,
// contact included: a bead that starts resting on a plane, pressed in by the Hertz depth that
// carries its weight, starts at rest in every integrator. (Contact was once left out of a₀: the
// bead started falling at g, and generalised-α carried that acceleration into its first steps.)

#include "ancfnet/integrators/initial_acceleration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/integrators/explicit_verlet.hpp"
#include "ancfnet/integrators/generalized_alpha.hpp"
#include "ancfnet/integrators/implicit_midpoint.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kMass = 0.01;      // kg
constexpr double kGravity = 9.81;   // m/s²
constexpr double kStiffness = 1e6;  // N/m^1.5
constexpr double kRadius = 0.002;   // m
// Hertz: k δ^1.5 = m g.
const double kDepth = std::pow(kMass * kGravity / kStiffness, 1.0 / 1.5);

// The bead's centre at height z above the plane z = 0.
Model MakeBead(double z) {
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -kGravity));
  builder.AddPointMass("bead", kMass, Vector3d(0.0, 0.0, z));
  ContactSpec spec;
  spec.normal = MakeHertzContactLaw(kStiffness);
  spec.point_mass_radius = kRadius;
  spec.targets.push_back({.kind = ContactTarget::Kind::kPlane, .name = "floor"});
  builder.SetContact(spec);
  return builder.Build();
}

template <class Integrator, class... Settings>
double InitialVerticalAcceleration(const Model& model, const Settings&... settings) {
  Integrator integrator(model, settings...);
  State state = MakeInitialState(model);
  EXPECT_TRUE(integrator.Initialize(&state));
  return state.a[model.point_masses()[0].dof + 2];
}

TEST(InitialAcceleration, ABeadRestingOnAPlaneStartsAtRestInEveryIntegrator) {
  const Model model = MakeBead(kRadius - kDepth);
  DynamicSettings settings;
  settings.time_step = 1e-3;
  // The residual force is the rounding of m g against k δ^1.5: 1e-9 g is far below the g of a
  // start without contact.
  const double tolerance = 1e-9 * kGravity;
  EXPECT_NEAR(InitialVerticalAcceleration<GeneralizedAlphaIntegrator>(model, settings), 0.0,
              tolerance);
  EXPECT_NEAR(InitialVerticalAcceleration<ImplicitMidpointIntegrator>(model, settings), 0.0,
              tolerance);
  EXPECT_NEAR(InitialVerticalAcceleration<ExplicitVerletIntegrator>(model), 0.0, tolerance);
}

TEST(InitialAcceleration, ABeadAboveThePlaneFallsAtG) {
  const Model model = MakeBead(2.0 * kRadius);
  DynamicSettings settings;
  settings.time_step = 1e-3;
  EXPECT_NEAR(InitialVerticalAcceleration<GeneralizedAlphaIntegrator>(model, settings), -kGravity,
              1e-12 * kGravity);
}

}  // namespace
}  // namespace ancfnet
