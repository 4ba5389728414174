// Capsule chains of the threads against rigid targets (ContactSpec::TargetGeometry::kCapsules).
//  1. A taut elastic thread of 4 elements, pinned at both ends 1 m apart, sagging under gravity
//     onto a thin rod (radius 1 mm) across its span: its 2 inspection spheres per element are
//     125 mm apart, so the rod slips between them and the thread sags through it to its free
//     sag; its capsules catch the rod, and the thread rests on it, the material point above the
//     rod's axis at z_top + r within r/10.
//  2. A thread whose ends slide freely up and down (x, y held) hangs over a horizontal
//     cylinder: at rest the cylinder carries the whole weight, Σ f_z = μ L g (statics: nothing
//     else holds the thread up), within 1 %.
// Both settle under mass-proportional Rayleigh damping (α = 50 /s, about critical for the
// thread's first mode).

#include <gtest/gtest.h>

#include <cstdio>

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

constexpr double kRadius = 1e-3;  // thread radius r (m)
constexpr double kGravity = 9.81;

// A 1 m thread along x at z = z0 (E = 100 MPa, 2 mm, nylon's density), under gravity.
ModelBuilder MakeThread(int elements, double z0) {
  Material rubber{.youngs_modulus = 1e8, .density = 1140, .axial_damping_time = 1e-3};
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0, 0, -kGravity));
  builder.SetRayleighDamping({.alpha = 50.0});
  builder.AddCable({.name = "thread",
                    .start = Vector3d(0, 0, z0),
                    .end = Vector3d(1, 0, z0),
                    .num_elements = elements,
                    .properties = MakeCableProperties(rubber, MakeCircleSection(2 * kRadius))});
  return builder;
}

ContactTarget Rod(double x, double z, double radius) {
  ContactTarget rod;
  rod.kind = ContactTarget::Kind::kCylinder;
  rod.name = "rod";
  rod.point = Vector3d(x, 0, z);
  rod.normal = Vector3d::UnitY();
  rod.radius = radius;
  rod.half_length = 0.1;
  return rod;
}

ContactSpec MakeContact(ContactSpec::TargetGeometry geometry, const ContactTarget& target) {
  ContactSpec spec;
  spec.normal = MakeLinearContactLaw(1e4, 1.0);
  spec.target_geometry = geometry;
  spec.points_per_element = 2;
  spec.targets.push_back(target);
  return spec;
}

// Position of the material point at arc fraction s of the single cable.
Vector3d PointAt(const Model& model, const VectorXd& q, double s) {
  const Index elements = static_cast<Index>(model.elements().size());
  const Index e = std::min<Index>(static_cast<Index>(s * elements), elements - 1);
  const CableElement& element = model.elements()[e];
  const Vector4d shape = CalcHermiteShape(s * elements - e, element.parameters.length).s;
  Vector3d r = Vector3d::Zero();
  for (int k = 0; k < 4; ++k) r += shape[k] * q.segment<3>(element.dofs[3 * k]);
  return r;
}

struct Rest {
  double z_at_rod = 0.0;  // thread centre line above the rod (m)
  double lowest = 0.0;    // lowest node (m)
  TargetContact::Summary contact;
};

Rest ThreadOverARod(ContactSpec::TargetGeometry geometry) {
  constexpr double kRodX = 0.45, kRodTop = -0.004, kRodRadius = 1e-3;
  ModelBuilder builder = MakeThread(4, 0.0);
  builder.AddPin({"thread", 0.0});
  builder.AddPin({"thread", 1.0});
  builder.SetContact(MakeContact(geometry, Rod(kRodX, kRodTop - kRodRadius, kRodRadius)));
  const Model model = builder.Build();
  const State state = verification::RunToEnd(model, 1e-3, 1.0);
  Rest rest;
  rest.z_at_rod = PointAt(model, state.q, kRodX).z();
  rest.lowest = 0.0;
  for (Index node = 0; node < model.num_nodes(); ++node)
    rest.lowest = std::min(rest.lowest, state.q[model.NodePositionDof(node) + 2]);
  rest.contact = TargetContact(model).Summarize(state.q, state.v, state.contact_history);
  return rest;
}

TEST(TargetCapsuleContact, CapsulesCatchAThinRodThatInspectionSpheresMiss) {
  constexpr double kRodTop = -0.004;
  const Rest spheres = ThreadOverARod(ContactSpec::TargetGeometry::kSpheres);
  const Rest capsules = ThreadOverARod(ContactSpec::TargetGeometry::kCapsules);
  std::printf(
      "thread over a 1 mm rod (top z = %.4f m): spheres z = %.5f m at the rod, lowest node "
      "%.5f m, %d contacts; capsules z = %.5f m (expected %.5f), lowest node %.5f m, %d "
      "contacts, N = %.4e N, deepest %.2e m\n",
      kRodTop, spheres.z_at_rod, spheres.lowest, spheres.contact.active, capsules.z_at_rod,
      kRodTop + kRadius, capsules.lowest, capsules.contact.active, capsules.contact.normal_force,
      capsules.contact.max_penetration);
  // Spheres: no contact, the thread passes the rod and hangs below its bottom.
  EXPECT_EQ(spheres.contact.active, 0);
  EXPECT_LT(spheres.z_at_rod, kRodTop - 2e-3 - kRadius);
  // Capsules: resting on the rod.
  EXPECT_GE(capsules.contact.active, 1);
  EXPECT_LT(capsules.contact.max_penetration, 0.1 * kRadius);
  EXPECT_NEAR(capsules.z_at_rod, kRodTop + kRadius, 0.1 * kRadius);
  EXPECT_GT(capsules.lowest, spheres.lowest);
}

TEST(TargetCapsuleContact, CylinderCarriesTheWeightOfAThreadWithSlidingEnds) {
  constexpr double kCylinderRadius = 0.02;
  ModelBuilder builder = MakeThread(5, kRadius);
  const CoordinateMask horizontal = {true, true, false, false, false, false};
  builder.FixCoordinates({"thread", 0.0}, horizontal);
  builder.FixCoordinates({"thread", 1.0}, horizontal);
  ContactSpec spec = MakeContact(ContactSpec::TargetGeometry::kCapsules,
                                 Rod(0.5, -kCylinderRadius, kCylinderRadius));
  spec.capsules_per_element = 5;  // the top of the cylinder inside a capsule
  builder.SetContact(spec);
  const Model model = builder.Build();
  const State state = verification::RunToEnd(model, 1e-3, 1.0);
  std::vector<ContactPoint> records;
  TargetContact(model).CollectContacts(state.q, state.v, state.contact_history, &records);
  double lift = 0.0;
  for (const ContactPoint& r : records) lift += r.force_W.z();
  const double weight = model.cables()[0].properties.mass_per_length * 1.0 * kGravity;
  std::printf("thread over a cylinder, ends sliding: %zu contacts, Σ f_z = %.6e N, weight %.6e N\n",
              records.size(), lift, weight);
  EXPECT_NEAR(lift / weight, 1.0, 1e-2);
}

}  // namespace
}  // namespace ancfnet
