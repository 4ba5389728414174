// The complete Jacobians of the target-contact forces (issue 17) against central differences,
// both ∂Q/∂q (weights {0, 0, 1}) and ∂Q/∂q̇ (weights {0, 1, 0}) as the iteration matrix assembles
// them, to 10⁻⁶ of the matrix norm: a cable sliding with friction over curved targets (the
// tangent plane turns with the probe: sphere, cylinder, capsule, box edge, mesh; a box face as
// the flat reference), with inspection spheres and with capsule chains (t* moves), with the tanh
// law and the LuGre law stepped over h; and the same targets carried by a moving, rotated,
// spinning rigid body (the variation of G, the bristle turning with the body, the contact point
// and t* moving with the body's pose, the cable–body cross terms).

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ancfnet/contact/mesh/icosphere.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/forces/test/target_contact_check.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

constexpr double kTolerance = 1e-6;

const FrictionLaw kTanh = MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1);
const FrictionLaw kLuGre = MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1);

// A target in its own frame and the ends of a cable line across it, pressed into it near its
// middle (the thread's radius is 2 mm).
struct TargetCase {
  std::string name;
  ContactTarget target;
  Vector3d a, b;
};

std::vector<TargetCase> Targets() {
  std::vector<TargetCase> cases;
  // Across the top of a 0.3 m sphere, cylinder and capsule (axes along y), 1 mm deep at most.
  // The node between the cable's two elements lies at x = −0.03, so that the deepest point of a
  // capsule (x ≈ 0) lies inside its axis.
  const Vector3d a(-0.23, 0.01, 0.299), b(0.17, -0.02, 0.2985);
  ContactTarget sphere;
  sphere.kind = ContactTarget::Kind::kSphere;
  sphere.radius = 0.3;
  cases.push_back({"sphere", sphere, a, b});
  ContactTarget cylinder;
  cylinder.kind = ContactTarget::Kind::kCylinder;
  cylinder.normal = Vector3d::UnitY();
  cylinder.radius = 0.3;
  cylinder.half_length = 0.2;
  cases.push_back({"cylinder", cylinder, a, b});
  ContactTarget capsule = cylinder;
  capsule.kind = ContactTarget::Kind::kCapsule;
  capsule.half_length = 0.1;
  cases.push_back({"capsule", capsule, a, b});
  // Over the edge x = 0, z = 0.3 (along y) of a box below z = 0.3 and behind x = 0, 1 mm above
  // it, sloping down by 1 in 40.
  ContactTarget edge;
  edge.kind = ContactTarget::Kind::kBox;
  edge.point = Vector3d(-0.5, 0.0, -0.2);
  edge.half_extents = Vector3d(0.5, 0.5, 0.5);
  cases.push_back({"box edge", edge, Vector3d(-0.219, 0.01, 0.301 + 0.025 * 0.219),
                   Vector3d(0.181, -0.02, 0.301 - 0.025 * 0.181)});
  // Across the top face z = 0.1 of a turned box, 1.2 to 1.5 mm deep.
  ContactTarget face;
  face.kind = ContactTarget::Kind::kBox;
  face.half_extents = Vector3d(0.3, 0.3, 0.1);
  face.rotation = Eigen::AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix();
  cases.push_back({"box face", face, Vector3d(-0.23, 0.01, 0.1005), Vector3d(0.17, -0.02, 0.1008)});
  // Just outside a faceted sphere (its signed distance is C¹ there), over its vertex at the top,
  // (0, 0, 0.3), whose Voronoi region curves the distance like a sphere's of radius φ.
  ContactTarget mesh;
  mesh.kind = ContactTarget::Kind::kMesh;
  mesh.mesh = std::make_shared<const MeshBvh>(MakeIcosphere(0.3, 4));
  cases.push_back({"mesh", mesh, Vector3d(-0.22, 0.001, 0.3015), Vector3d(0.18, -0.001, 0.3014)});
  return cases;
}

// The body carrying the target, when there is one: at p, turned by R, moving and spinning.
const Vector3d kBodyPosition(0.01, -0.02, 0.03);
const Matrix3d kBodyRotation =
    Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();

Model MakeCableOnTarget(const TargetCase& c, const std::optional<FrictionLaw>& friction,
                        ContactSpec::TargetGeometry geometry, bool on_body) {
  ModelBuilder builder;
  Vector3d a = c.a, b = c.b;
  ContactTarget target = c.target;
  if (on_body) {
    builder.AddRigidBody({.name = "target",
                          .mass = 5.0,
                          .inertia = Vector3d(0.2, 0.3, 0.4).asDiagonal(),
                          .position = kBodyPosition,
                          .orientation = kBodyRotation,
                          .velocity = Vector3d(0.1, -0.2, 0.05),
                          .angular_velocity = Vector3d(0.3, -0.5, 0.7)});
    a = kBodyPosition + kBodyRotation * a;
    b = kBodyPosition + kBodyRotation * b;
    target.body_name = "target";
  }
  test::AddTestRope(a, b, &builder);
  ContactSpec spec = test::MakeTestContactSpec(friction);
  spec.target_geometry = geometry;
  spec.capsules_per_element = 3;
  spec.targets.push_back(target);
  builder.SetContact(spec);
  return builder.Build();
}

// The relative errors of both Jacobians of the contact forces at the initial positions, the
// cable sliding at (4, 2.5, 0) cm/s plus a perturbation of every coordinate's rate, with impact
// speeds of both signs and (LuGre: `step` > 0) the bristles deflected by ± `bristle`.
struct Errors {
  double stiffness = 0.0, damping = 0.0;
  int active = 0;
};

Errors CalcErrors(const Model& model, double step = 0.0,
                  const Vector3d& bristle = Vector3d::Zero()) {
  TargetContact contact(model);
  contact.SetStepSize(step);
  const State state = MakeInitialState(model);
  VectorXd v = state.v;
  for (Index node = 0; node < model.num_nodes(); ++node)
    v.segment<3>(model.NodePositionDof(node)) += Vector3d(0.04, 0.025, 0.0);
  for (Index i = 0; i < 6 * model.num_nodes(); ++i) v[i] += 0.01 * std::sin(1.7 * i + 0.3);
  std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)));
  for (std::size_t i = 0; i < history.size(); ++i) {
    history[i].speed = i % 2 ? 0.5 : -0.3;
    history[i].bristle = (i % 3 ? 1.0 : -0.5) * bristle;
  }
  Errors e;
  e.active = contact.Summarize(state.q, v, history).active;
  e.stiffness = test::CalcTargetContactJacobianError(model, contact, history, state.q, v,
                                                     {.mass = 0, .damping = 0, .stiffness = 1});
  e.damping = test::CalcTargetContactJacobianError(model, contact, history, state.q, v,
                                                   {.mass = 0, .damping = 1, .stiffness = 0});
  return e;
}

void ExpectExactJacobians(const std::string& what, const Model& model, double step = 0.0,
                          const Vector3d& bristle = Vector3d::Zero()) {
  const Errors e = CalcErrors(model, step, bristle);
  std::printf("%-44s %2d touching: stiffness %.2e, damping %.2e\n", what.c_str(), e.active,
              e.stiffness, e.damping);
  EXPECT_GE(e.active, 1) << what;
  EXPECT_LT(e.stiffness, kTolerance) << what << ": ∂Q/∂q";
  EXPECT_LT(e.damping, kTolerance) << what << ": ∂Q/∂q̇";
}

std::string Name(const TargetCase& c, ContactSpec::TargetGeometry geometry, const char* law,
                 bool on_body) {
  return std::string(on_body ? "body " : "") + c.name + ", " +
         (geometry == ContactSpec::TargetGeometry::kSpheres ? "spheres" : "capsules") + ", " + law;
}

// (1), (2): the tangent plane turns with the probe's position on a curved target; the contact
// point and (capsules) t* move with it.
TEST(ContactJacobian, FrictionOnFixedTargetsMatchesFiniteDifferences) {
  for (const TargetCase& c : Targets())
    for (const auto geometry :
         {ContactSpec::TargetGeometry::kSpheres, ContactSpec::TargetGeometry::kCapsules}) {
      ExpectExactJacobians(Name(c, geometry, "tanh", false),
                           MakeCableOnTarget(c, kTanh, geometry, false));
      // The bristles stepped over 1 ms from a deflection partly off the tangent plane.
      ExpectExactJacobians(Name(c, geometry, "LuGre", false),
                           MakeCableOnTarget(c, kLuGre, geometry, false), 1e-3,
                           Vector3d(3e-5, -1e-5, 5e-6));
    }
}

// (3): frictionless contact with a body: the variation of G (the moment arm of the reaction
// turning with the body) and of the normal with the rotation.
TEST(ContactJacobian, NormalContactWithABodyMatchesFiniteDifferences) {
  for (const TargetCase& c : Targets())
    for (const auto geometry :
         {ContactSpec::TargetGeometry::kSpheres, ContactSpec::TargetGeometry::kCapsules})
      ExpectExactJacobians(Name(c, geometry, "frictionless", true),
                           MakeCableOnTarget(c, std::nullopt, geometry, true));
}

// (3), (4): friction on a target carried by a moving, spinning body: the slip velocity depends
// on the pose through the surface point, the bristles turn with the body, t* moves with the
// pose.
TEST(ContactJacobian, FrictionWithABodyMatchesFiniteDifferences) {
  for (const TargetCase& c : Targets())
    for (const auto geometry :
         {ContactSpec::TargetGeometry::kSpheres, ContactSpec::TargetGeometry::kCapsules}) {
      ExpectExactJacobians(Name(c, geometry, "tanh", true),
                           MakeCableOnTarget(c, kTanh, geometry, true));
      ExpectExactJacobians(Name(c, geometry, "LuGre", true),
                           MakeCableOnTarget(c, kLuGre, geometry, true), 1e-3,
                           Vector3d(2e-5, -1e-5, 4e-6));
    }
}

}  // namespace
}  // namespace ancfnet
