// Contact with triangle-mesh targets through the full solver: a ball (point mass) dropped on a
// box read from STL comes to rest at the penetration m g/k of the linear law; a rope dropped on
// it rests without sinking in; a ball striking a faceted sphere (icosphere) rebounds off the
// face it hits with the restitution of its law, and within the facetting's bound of the rebound
// off the exact sphere.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

constexpr double kGravity = 9.81;

// CTest sets ANCFNET_SOURCE_DIR; by hand, run from the repository's root.
std::filesystem::path DataDir() {
  const char* dir = std::getenv("ANCFNET_SOURCE_DIR");
  return (dir != nullptr ? std::filesystem::path(dir) : std::filesystem::current_path()) / "tests" /
         "data";
}

// tests/data/unit_cube.stl scaled to a 0.2 m box whose top face is the plane z = 0.
ContactTarget MeshBox() {
  TriangleMesh mesh = LoadTriangleMesh(DataDir() / "unit_cube.stl");
  TransformTriangleMesh(0.2, Matrix3d::Identity(), Vector3d(0, 0, -0.1), &mesh);
  ContactTarget box;
  box.kind = ContactTarget::Kind::kMesh;
  box.name = "box";
  box.mesh = std::make_shared<const MeshBvh>(std::move(mesh));
  return box;
}

TEST(MeshContact, BallDroppedOnAMeshBoxRestsAtTheLinearLawsPenetration) {
  constexpr double kMass = 0.1, kRadius = 0.01, kStiffness = 1e4;
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  const Vector3d start(0.03, -0.02, 0.05);
  builder.AddPointMass("ball", kMass, start);
  ContactSpec spec;
  spec.normal = MakeLinearContactLaw(kStiffness, 10.0);  // damping ratio 0.16
  spec.point_mass_radius = kRadius;
  spec.targets.push_back(MeshBox());
  builder.SetContact(spec);
  const Model model = builder.Build();
  DynamicSettings settings;
  settings.time_step = 5e-4;
  settings.end_time = 1.5;
  State state = MakeInitialState(model);
  double max_penetration = 0.0;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        max_penetration = std::max(max_penetration, kRadius - s.q[2]);
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  const double expected = kMass * kGravity / kStiffness;  // N = k δ = m g
  const double penetration = kRadius - state.q[2];
  std::printf(
      "ball on a mesh box: δ = %.6e m (m g/k = %.6e m, relative error %.1e), first impact "
      "%.3e m, |v| %.1e\n",
      penetration, expected, penetration / expected - 1.0, max_penetration, state.v.norm());
  EXPECT_NEAR(penetration / expected, 1.0, 1e-6);
  EXPECT_LT(state.v.norm(), 1e-6);
  // The top face pushes straight up: no drift sideways.
  EXPECT_NEAR(state.q[0], start[0], 1e-12);
  EXPECT_NEAR(state.q[1], start[1], 1e-12);
  // The first impact at √(2 g h) sinks about v √(m/k) (less the damping's share).
  EXPECT_GT(max_penetration, 0.5 * std::sqrt(2 * kGravity * 0.04) * std::sqrt(kMass / kStiffness));
}

// The rope of tests/verification/target_contact_test.cpp (nylon, 2 mm), 0.15 m long, dropped
// across the box's top face.
TEST(MeshContact, RopeDroppedOnAMeshBoxRestsOnIt) {
  Material nylon{.youngs_modulus = 3e9,
                 .density = 1140,
                 .axial_damping_time = 1e-3,
                 .bending_damping_time = 1e-3};
  const CableProperties p = MakeCableProperties(nylon, MakeCircleSection(0.002));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  builder.AddCable({.name = "rope",
                    .start = Vector3d(-0.07, 0.01, 0.006),
                    .end = Vector3d(0.08, 0.03, 0.006),
                    .num_elements = 6,
                    .properties = p});
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.3);
  spec.friction = MakeTanhFriction(0.3, 0.3, 1e-3, 1e-2);
  spec.targets.push_back(MeshBox());
  builder.SetContact(spec);
  const Model model = builder.Build();
  const State state = verification::RunToEnd(model, 1e-4, 0.3);
  const TargetContact::Summary s =
      TargetContact(model).Summarize(state.q, state.v, state.contact_history);
  const double length = std::hypot(0.15, 0.02);
  const double weight = p.mass_per_length * length * kGravity;
  std::printf(
      "rope on a mesh box: %d touching spheres, N = %.6f N (weight %.6f N, relative %.1e), "
      "deepest %.2e m\n",
      s.active, s.normal_force, weight, s.normal_force / weight - 1.0, s.max_penetration);
  EXPECT_GT(s.active, 30);
  EXPECT_LT(s.max_penetration, 0.1 * 0.001);
  EXPECT_NEAR(s.normal_force, weight, 1e-3 * weight);
}

struct Rebound {
  Vector3d velocity = Vector3d::Zero();
  double max_penetration = 0.0;
  Vector3d position_at_max = Vector3d::Zero();
};

// A ball of radius r flying at v₀ = −e_z on the line through (b_x, b_y) onto a target around the
// origin of radius ≈ R, from 0.1 mm off the exact sphere; no gravity; implicit midpoint rule with
// 4000 steps per Hertz contact time (as tests/verification/target_contact_test.cpp's plane
// impacts).
Rebound Strike(const ContactTarget& target, const NormalLaw& law, double R, double r,
               const Eigen::Vector2d& b) {
  constexpr double kMass = 0.1, kSpeed = 1.0;
  ModelBuilder builder;
  const double z0 = std::sqrt(std::pow(R + r + 1e-4, 2) - b.squaredNorm());
  builder.AddPointMass("ball", kMass, Vector3d(b.x(), b.y(), z0), Vector3d(0, 0, -kSpeed));
  ContactSpec spec;
  spec.normal = law;
  spec.point_mass_radius = r;
  spec.targets.push_back(target);
  builder.SetContact(spec);
  const Model model = builder.Build();
  const double delta_max = std::pow(5.0 * kMass * kSpeed * kSpeed / (4.0 * law.stiffness), 0.4);
  const double hertz_time = 2.943275 * delta_max / kSpeed;
  DynamicSettings settings;
  settings.integrator = IntegratorType::kImplicitMidpoint;
  settings.time_step = hertz_time / 4000.0;
  settings.end_time = 6e-4 / kSpeed + 3.0 * hertz_time;
  settings.newton.relative_tolerance = 1e-12;
  settings.newton.absolute_tolerance = 1e-15;
  State state = MakeInitialState(model);
  const TargetContact contact(model);
  Rebound rebound;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        const TargetContact::Summary summary = contact.Summarize(s.q, s.v, s.contact_history);
        if (summary.max_penetration > rebound.max_penetration) {
          rebound.max_penetration = summary.max_penetration;
          rebound.position_at_max = s.q.segment<3>(0);
        }
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  rebound.velocity = state.v.segment<3>(0);
  return rebound;
}

TEST(MeshContact, BounceOffAFacetedSphere) {
  constexpr double R = 0.1, r = 0.01;
  const auto sphere_mesh = std::make_shared<const MeshBvh>(MakeIcosphere(R, 3));  // 1280 faces
  // The facetting: the largest angle between a face's normal and the sphere's normal at a point
  // of the face (at its corners).
  double facet_angle = 0.0;
  const TriangleMesh& m = sphere_mesh->mesh();
  for (Index t = 0; t < m.triangles.cols(); ++t)
    for (int k = 0; k < 3; ++k)
      facet_angle = std::max(facet_angle,
                             std::acos(std::min(1.0, sphere_mesh->normals().face.col(t).dot(
                                                         m.vertices.col(m.triangles(k, t)) / R))));
  // Aimed at the centre of the face whose normal is nearest 20° from the vertical in the x–z
  // plane: the ball's centre passes through centroid + r n_f.
  const Vector3d aim(std::sin(0.35), 0.0, std::cos(0.35));
  Index face = 0;
  (sphere_mesh->normals().face.transpose() * aim).maxCoeff(&face);
  const Vector3d centroid =
      (m.vertices.col(m.triangles(0, face)) + m.vertices.col(m.triangles(1, face)) +
       m.vertices.col(m.triangles(2, face))) /
      3.0;
  const Vector3d through = centroid + r * sphere_mesh->normals().face.col(face);
  const Eigen::Vector2d b = through.head<2>();
  ContactTarget faceted;
  faceted.kind = ContactTarget::Kind::kMesh;
  faceted.mesh = sphere_mesh;
  ContactTarget exact;
  exact.kind = ContactTarget::Kind::kSphere;
  exact.radius = R;
  const NormalLaw law = MakeDissipativeContactLaw(NormalLawKind::kFlores, 1e7, 0.5);
  const double e = CalcRestitutionForHysteresisFactor(law.hysteresis_factor());
  const Vector3d v0(0, 0, -1);
  const Rebound on_mesh = Strike(faceted, law, R, r, b);
  const Rebound on_sphere = Strike(exact, law, R, r, b);
  // Struck that face only (the ball slides ~0.7 mm during the contact, the face's inradius is
  // 4 mm): the contact is a plane's, and the law's restitution holds along its normal.
  const MeshDistance hit = sphere_mesh->CalcDistance(on_mesh.position_at_max);
  ASSERT_EQ(hit.feature, MeshFeature::kFace);
  ASSERT_EQ(hit.feature_index, face);
  const Vector3d& n = hit.normal;
  const double measured = -on_mesh.velocity.dot(n) / v0.dot(n);
  const Vector3d change = on_mesh.velocity - v0;
  const double sideways = (change - change.dot(n) * n).norm();
  // Off the exact sphere, v' = v₀ − (1 + e)(v₀·n_s) n_s; a normal turned by θ changes it by at
  // most 2 (1 + e) |v₀| θ: θ the angle between the struck face's normal and the sphere's normal
  // where the ball strikes the exact sphere, at most the facet angle for any aim.
  const double deviation = (on_mesh.velocity - on_sphere.velocity).norm();
  const double angle = std::acos(std::min(1.0, n.dot(on_sphere.position_at_max.normalized())));
  const double bound = 2.0 * (1.0 + e) * v0.norm() * angle;
  std::printf(
      "bounce off an icosphere (1280 faces, facet angle %.3f°): e along the face normal "
      "%.5f (law %.5f, difference %.1e), sideways %.1e m/s; |v'_mesh − v'_sphere| = %.5f m/s "
      "(bound "
      "%.5f for the %.4f° between the normals; %.4f for the facet angle)\n",
      facet_angle * 180.0 / std::numbers::pi, measured, e, measured - e, sideways, deviation, bound,
      angle * 180.0 / std::numbers::pi, 2.0 * (1.0 + e) * v0.norm() * facet_angle);
  EXPECT_LT(angle, facet_angle);
  EXPECT_NEAR(measured, e, 1e-4);
  EXPECT_LT(sideways, 1e-6);
  EXPECT_LT(deviation, bound);
  // The exact sphere's own rebound, as a check of the comparison.
  const Vector3d n_s = on_sphere.position_at_max.normalized();
  EXPECT_NEAR(-on_sphere.velocity.dot(n_s) / v0.dot(n_s), e, 2e-3);
}

}  // namespace
}  // namespace ancfnet
