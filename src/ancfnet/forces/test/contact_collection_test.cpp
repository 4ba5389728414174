// The records of the active contacts (TargetContact::CollectContacts): a point mass sliding on a
// plane gets the normal force of the linear law and the friction of the tanh law at hand-computed
// values; for a cable pressed into a sphere the records' forces add up to the generalised forces
// AddForces applies and agree with Summarize.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

TEST(CollectContacts, PointMassSlidingOnAPlane) {
  constexpr double kRadius = 0.01, kDepth = 2e-4, k = 1e4, c = 10.0, mu = 0.3;
  ModelBuilder builder;
  builder.AddPointMass("block", 0.1, Vector3d(0.3, 0.2, kRadius - kDepth));
  ContactSpec spec;
  spec.normal = MakeLinearContactLaw(k, c);
  spec.friction = MakeTanhFriction(mu, mu, 1e-3, 1.0);
  spec.point_mass_radius = kRadius;
  ContactTarget far, ground;
  far.name = "far";
  far.point = Vector3d(0, 0, -1);  // a second plane below, not touched
  ground.name = "ground";
  spec.targets = {far, ground};
  builder.SetContact(spec);
  const Model model = builder.Build();
  const TargetContact contact(model);
  const VectorXd q = model.initial_positions();
  const VectorXd v = Vector3d(0.5, 0.0, -0.1);
  const std::vector<ContactPairHistory> history(2);
  std::vector<ContactPoint> records;
  contact.CollectContacts(q, v, history, &records);
  ASSERT_EQ(records.size(), 1u);
  const ContactPoint& r = records[0];
  EXPECT_EQ(r.target, 1);
  EXPECT_EQ(r.point_mass, 0);
  EXPECT_EQ(r.element, -1);
  EXPECT_NEAR(r.penetration, kDepth, 1e-15);
  EXPECT_LT((r.point_W - Vector3d(0.3, 0.2, 0.0)).norm(), 1e-15);
  EXPECT_LT((r.normal_W - Vector3d::UnitZ()).norm(), 1e-15);
  const double normal = k * kDepth + c * 0.1;
  EXPECT_NEAR(r.normal_force, normal, 1e-12);
  const Vector3d friction(-mu * normal * std::tanh(0.5 / 1e-3), 0.0, 0.0);
  EXPECT_LT((r.friction_force_W - friction).norm(), 1e-12);
  EXPECT_LT((r.force_W - (normal * Vector3d::UnitZ() + friction)).norm(), 1e-12);
}

TEST(CollectContacts, RecordsAddUpToTheAppliedForces) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  ModelBuilder builder;
  builder.AddCable({.name = "rope",
                    .start = Vector3d(-0.2, 0.01, 0.299),
                    .end = Vector3d(0.2, -0.02, 0.2985),
                    .num_elements = 2,
                    .properties = MakeCableProperties(nylon, MakeCircleSection(0.004))});
  ContactSpec spec;
  spec.normal = MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e6, 0.4);
  spec.friction = MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1);
  spec.points_per_element = 5;
  ContactTarget ball;
  ball.kind = ContactTarget::Kind::kSphere;
  ball.name = "ball";
  ball.radius = 0.3;
  spec.targets.push_back(ball);
  builder.SetContact(spec);
  const Model model = builder.Build();
  const TargetContact contact(model);
  const VectorXd q = model.initial_positions();
  VectorXd v(model.num_dofs());
  for (Index i = 0; i < v.size(); ++i) v[i] = 0.01 * std::sin(1.7 * i + 0.3);
  const std::vector<ContactPairHistory> history(static_cast<std::size_t>(CountContactPairs(model)),
                                                {.speed = 0.2});
  std::vector<ContactPoint> records;
  contact.CollectContacts(q, v, history, &records);
  ASSERT_GE(records.size(), 2u);

  // The position shape functions sum to 1 (S₁ + S₃ = 1): the forces on the nodes' positions add
  // up to −Σ f.
  Workspace ws(model);
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  contact.AddForces(q, v, history, ws);
  std::set<Index> position_dofs;
  for (const CableElement& element : model.elements())
    position_dofs.insert({element.dofs[0], element.dofs[6]});
  ASSERT_EQ(position_dofs.size(), 3u);
  Vector3d applied = Vector3d::Zero();
  for (Index dof : position_dofs) applied -= ws.internal_force.segment<3>(dof);
  Vector3d recorded = Vector3d::Zero();
  double normal = 0.0, deepest = 0.0;
  for (const ContactPoint& r : records) {
    recorded += r.force_W;
    normal += r.normal_force;
    deepest = std::max(deepest, r.penetration);
    EXPECT_EQ(r.target, 0);
    EXPECT_GE(r.element, 0);
    EXPECT_NEAR(r.point_W.norm(), 0.3, 1e-12);  // on the sphere's surface
    EXPECT_LT((r.normal_W - r.point_W / 0.3).norm(), 1e-12);
    EXPECT_NEAR(r.normal_W.dot(r.friction_force_W), 0.0, 1e-12);
    EXPECT_LT((r.force_W - r.normal_force * r.normal_W - r.friction_force_W).norm(), 1e-12);
  }
  EXPECT_LT((applied - recorded).norm(), 1e-10 * recorded.norm());
  const TargetContact::Summary s = contact.Summarize(q, v, history);
  EXPECT_EQ(s.active, static_cast<int>(records.size()));
  EXPECT_NEAR(s.normal_force, normal, 1e-12 * normal);
  EXPECT_EQ(s.max_penetration, deepest);
}

}  // namespace
}  // namespace ancfnet
