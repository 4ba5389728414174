#pragma once
/// @file Models shared by the verification cases, built through the public API.

#include <gtest/gtest.h>

#include <optional>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet::verification {

/// Cantilever of the static example: L = 1 m, E = 2e11 Pa, 10 × 10 mm square, clamped at
/// x = 0, along +x. EI = 2e11 · 1e-8 / 12 N m².
inline ModelBuilder MakeCantilever(int elements, int axial_gauss_points = 3,
                                   int bending_gauss_points = 4) {
  Material steel{.youngs_modulus = 2.0e11, .density = 7800.0};
  CableProperties properties = MakeCableProperties(steel, MakeRectangleSection(0.01, 0.01));
  properties.axial_gauss_points = axial_gauss_points;
  properties.bending_gauss_points = bending_gauss_points;
  ModelBuilder builder;
  builder.AddCable({.name = "beam",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = elements,
                    .properties = properties});
  builder.AddClamp({"beam", 0.0});
  return builder;
}

inline double CantileverBendingStiffness() { return 2.0e11 * 1e-8 / 12.0; }

/// Contact with one target, the plane through the origin with outward `normal` named "ground":
/// the normal law, the friction law (none: frictionless) and the point masses' radius.
inline ContactSpec MakePlaneContact(const NormalLaw& law, const Vector3d& normal,
                                    const std::optional<FrictionLaw>& friction = std::nullopt,
                                    double point_mass_radius = 0.0) {
  ContactSpec spec;
  spec.normal = law;
  spec.friction = friction;
  spec.point_mass_radius = point_mass_radius;
  ContactTarget plane;
  plane.name = "ground";
  plane.normal = normal;
  spec.targets.push_back(plane);
  return spec;
}

/// The state after a generalised-α run (default settings otherwise) from the initial state to
/// `end_time` with nominal step `time_step`, no outputs; a run that does not complete fails the
/// test.
inline State RunToEnd(const Model& model, double time_step, double end_time) {
  DynamicSettings settings;
  settings.time_step = time_step;
  settings.end_time = end_time;
  State state = MakeInitialState(model);
  const SolveResult result = SolveDynamic(
      model, settings, 0.0, [](const State&, const EnergyAccount&) {}, &state);
  EXPECT_TRUE(result.completed) << result.message;
  return state;
}

}  // namespace ancfnet::verification

namespace ancfnet::verification {

/// Flexible pendulum of the issue: L = 1 m, circular d = 0.01 m, E = 2e9 Pa, ρ = 1000 kg/m³,
/// pinned at the origin, released horizontal (along +x) under g = 9.81 m/s² along −z.
inline Model MakePendulum(int elements, double damping_time = 0.0) {
  Material material{.youngs_modulus = 2.0e9,
                    .density = 1000.0,
                    .axial_damping_time = damping_time,
                    .bending_damping_time = damping_time};
  const CableProperties properties = MakeCableProperties(material, MakeCircleSection(0.01));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "pendulum",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = elements,
                    .properties = properties});
  builder.AddPin({"pendulum", 0.0});
  return builder.Build();
}

}  // namespace ancfnet::verification
