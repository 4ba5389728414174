// Capture metrics on nets whose answer is known by construction: an octahedral net wrapped round a
// sphere (enclosed, every knot touching), the same net beside the target (a miss: no contact,
// nothing enclosed, escaped when they part), contact coverage counted from given contacts, and
// the safety factor of a thread stretched to a known tension.

#include "ancfnet/analysis/capture_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kHalfDiagonal = 1.0;  // a: the octahedron's knots at ±a on each axis (m)

// An octahedral net: 6 knots at ±a e_i, 12 threads along its edges (its hull's inradius is
// a/√3 = 0.577 a), the square round the equator as its mouth; and a sphere target of radius
// `target_radius` at `target_center`. The knots touch a target closer than their contact
// radius `knot_radius`; the threads' inspection spheres have radius `thread_radius`.
struct WrappedNet {
  Model model;
  double initial_mouth_area = 0.0;
};

WrappedNet MakeOctahedralNet(const Vector3d& target_center, double target_radius,
                             double knot_radius, double thread_radius,
                             const Vector3d& velocity = Vector3d::Zero()) {
  const double a = kHalfDiagonal;
  std::vector<Vector3d> knots = {Vector3d(a, 0, 0),  Vector3d(0, a, 0), Vector3d(-a, 0, 0),
                                 Vector3d(0, -a, 0), Vector3d(0, 0, a), Vector3d(0, 0, -a)};
  std::vector<std::array<Index, 2>> threads = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4},
                                               {2, 4}, {3, 4}, {0, 5}, {1, 5}, {2, 5}, {3, 5}};
  NetSpec spec;
  spec.name = "net";
  spec.topology = MakeGraphNet(knots, threads, {0, 1, 2, 3});
  spec.thread =
      MakeRopeProperties({.youngs_modulus = 1e9, .density = 1000}, MakeCircleSection(0.002));
  spec.knot_mass = 0.01;
  spec.velocity = velocity;
  ModelBuilder builder;
  AddNet(builder, spec);
  ContactSpec contact;
  contact.normal = MakeLinearContactLaw(1e4, 0.0);
  contact.point_mass_radius = knot_radius;
  contact.cable_radius = thread_radius;
  ContactTarget sphere;
  sphere.kind = ContactTarget::Kind::kSphere;
  sphere.name = "target";
  sphere.point = target_center;
  sphere.radius = target_radius;
  contact.targets = {sphere};
  builder.SetContact(contact);
  WrappedNet net{.model = builder.Build()};
  net.initial_mouth_area = 2.0 * a * a;  // the square of diagonal 2a
  return net;
}

std::vector<ContactPoint> Contacts(const Model& model, const State& state) {
  const TargetContact contact(model);
  std::vector<ContactPoint> records;
  contact.CollectContacts(state.q, state.v, state.contact_history, &records);
  return records;
}

TEST(CaptureMetrics, NetWrappedRoundASphereEnclosesItAndTouchesEverywhere) {
  // Target radius 0.5 a < a/√3: wholly inside the hull. Knots at a from the centre with contact
  // radius 0.55 a: each sinks 0.05 a. Edge midpoints at a/√2 = 0.707 a, inspection spheres of
  // 0.25 a: every thread sinks too.
  const WrappedNet net = MakeOctahedralNet(Vector3d::Zero(), 0.5, 0.55, 0.25);
  const State state = MakeInitialState(net.model);
  const CaptureMetrics m = CalcCaptureMetrics(net.model, state, 0, 0, Contacts(net.model, state),
                                              net.initial_mouth_area);
  EXPECT_TRUE(m.in_contact);
  EXPECT_EQ(m.enclosed_fraction, 1.0);
  EXPECT_NEAR(m.mouth_area_ratio, 1.0, 1e-14);
  EXPECT_EQ(m.knot_coverage, 1.0);
  EXPECT_EQ(m.thread_coverage, 1.0);
  EXPECT_FALSE(m.escaped);
  EXPECT_FALSE(m.has_tether);
}

TEST(CaptureMetrics, ThinThreadsAroundTheSphereLeaveOnlyTheKnotsTouching) {
  // Inspection spheres of 0.1 a reach 0.607 a from the centre: short of a target of 0.55 a.
  const WrappedNet net = MakeOctahedralNet(Vector3d::Zero(), 0.55, 0.5, 0.1);
  const State state = MakeInitialState(net.model);
  const CaptureMetrics m = CalcCaptureMetrics(net.model, state, 0, 0, Contacts(net.model, state),
                                              net.initial_mouth_area);
  EXPECT_EQ(m.knot_coverage, 1.0);
  EXPECT_EQ(m.thread_coverage, 0.0);
  EXPECT_EQ(m.enclosed_fraction, 1.0);  // 0.55 a < a/√3
}

TEST(CaptureMetrics, CoverageCountsEachKnotAndThreadOnceAndOnlyForItsTarget) {
  const WrappedNet net = MakeOctahedralNet(Vector3d(10, 0, 0), 0.5, 0.01, 0.01);
  const Model& model = net.model;
  const Net& octahedron = model.nets()[0];
  const State state = MakeInitialState(model);
  const auto knot = [&](int i) {
    ContactPoint c;
    c.target = 0;
    c.point_mass = octahedron.knots[i];
    return c;
  };
  const auto thread = [&](int j) {
    ContactPoint c;
    c.target = 0;
    c.element = model.cables()[octahedron.threads[j]].first_element;
    return c;
  };
  ContactPoint self = thread(7);
  self.target = -1;  // a self-contact does not touch the target
  const std::vector<ContactPoint> contacts = {knot(0),   knot(0),    knot(3), thread(2),
                                              thread(2), thread(11), self};
  const CaptureMetrics m = CalcCaptureMetrics(model, state, 0, 0, contacts, net.initial_mouth_area);
  EXPECT_TRUE(m.in_contact);
  EXPECT_DOUBLE_EQ(m.knot_coverage, 2.0 / 6.0);
  EXPECT_DOUBLE_EQ(m.thread_coverage, 2.0 / 12.0);
}

TEST(CaptureMetrics, NetThatMissesEnclosesNothingAndEscapesWhenTheyPart) {
  // Target 5 a to the side of the net: no contact, nothing enclosed. The net moving −x, away
  // from it: escaped; moving +x, towards it: not (yet) escaped.
  for (const double vx : {-1.0, 1.0}) {
    const WrappedNet net =
        MakeOctahedralNet(Vector3d(5, 0, 0), 0.5, 0.01, 0.01, Vector3d(vx, 0, 0));
    const State state = MakeInitialState(net.model);
    const std::vector<ContactPoint> contacts = Contacts(net.model, state);
    EXPECT_TRUE(contacts.empty());
    const CaptureMetrics m =
        CalcCaptureMetrics(net.model, state, 0, 0, contacts, net.initial_mouth_area);
    EXPECT_FALSE(m.in_contact);
    EXPECT_EQ(m.enclosed_fraction, 0.0);
    EXPECT_EQ(m.knot_coverage, 0.0);
    EXPECT_EQ(m.thread_coverage, 0.0);
    EXPECT_EQ(m.escaped, vx < 0.0) << "net velocity " << vx;
  }
}

TEST(CaptureMetrics, EscapeNeedsTheCentreOutsideAndMovingAway) {
  const Vector3d p_T(2, 0, 0), p_N(0, 0, 0), zero = Vector3d::Zero();
  EXPECT_TRUE(IsTargetEscaping(false, p_T, Vector3d(1, 0, 0), p_N, zero));
  EXPECT_FALSE(IsTargetEscaping(true, p_T, Vector3d(1, 0, 0), p_N, zero));
  EXPECT_FALSE(IsTargetEscaping(false, p_T, Vector3d(-1, 0, 0), p_N, zero));
  EXPECT_FALSE(IsTargetEscaping(false, p_T, Vector3d(1, 0, 0), p_N, Vector3d(1, 0, 0)));
  EXPECT_FALSE(IsTargetEscaping(false, p_T, Vector3d(0, 1, 0), p_N, zero));  // passing by
}

TEST(CaptureMetrics, SafetyFactorIsBreakingOverLargestTension) {
  EXPECT_DOUBLE_EQ(CalcSafetyFactor(1000.0, 250.0), 4.0);
  EXPECT_DOUBLE_EQ(CalcLoadRatio(250.0, 1000.0), 0.25);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(CalcSafetyFactor(inf, 250.0), inf);
  EXPECT_EQ(CalcSafetyFactor(1000.0, 0.0), inf);  // slack
  EXPECT_EQ(CalcLoadRatio(250.0, inf), 0.0);
  EXPECT_EQ(CalcLoadRatio(-5.0, 1000.0), 0.0);
}

TEST(CaptureMetrics, SafetyFactorOfAThreadStretchedToAKnownTension) {
  // A compliant two-knot net whose thread (breaking force 100 N) is stretched uniformly by
  // λ = 1.001 (nodes at λ x, slopes λ e_x): tension EA ε λ with ε = (λ² − 1)/2, exact for the
  // cable (docs/theory.md, "Tension recovery"); the safety factor is 100 N over it.
  NetSpec spec;
  spec.name = "rope";
  spec.topology = MakeGraphNet({Vector3d(0, 0, 0), Vector3d(1, 0, 0)}, {{0, 1}});
  spec.thread =
      MakeCableProperties({.youngs_modulus = 1e9, .density = 1000}, MakeCircleSection(0.002));
  spec.thread.tension_only = true;
  spec.elements_per_thread = 3;
  spec.knot_model = KnotModel::kCompliant;
  spec.knot_mass = 0.01;
  spec.link_law = MakeLinearLaw(1e4);
  spec.thread_breaking_force = 100.0;
  ModelBuilder builder;
  AddNet(builder, spec);
  ContactSpec contact;
  contact.normal = MakeLinearContactLaw(1e4, 0.0);
  ContactTarget sphere;
  sphere.kind = ContactTarget::Kind::kSphere;
  sphere.name = "target";
  sphere.point = Vector3d(0, 0, 5);
  sphere.radius = 0.5;
  contact.targets = {sphere};
  builder.SetContact(contact);
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  const double stretch = 1.001;
  const Cable& thread = model.cables()[model.nets()[0].threads[0]];
  for (Index node = thread.first_node; node <= thread.first_node + thread.num_elements; ++node) {
    const Index dof = model.NodePositionDof(node);
    state.q[dof] *= stretch;
    state.q.segment<3>(model.NodeSlopeDof(node)) = Vector3d(stretch, 0, 0);
  }
  const double tension = spec.thread.axial_stiffness * 0.5 * (stretch * stretch - 1.0) * stretch;
  const CaptureMetrics m = CalcCaptureMetrics(model, state, 0, 0, {}, 0.0);
  EXPECT_NEAR(m.thread_tension, tension, 1e-9 * tension);
  EXPECT_EQ(m.thread_breaking_force, 100.0);
  EXPECT_NEAR(CalcSafetyFactor(m.thread_breaking_force, m.thread_tension), 100.0 / tension,
              1e-9 * 100.0 / tension);
  EXPECT_EQ(m.mouth_area_ratio, 0.0);   // no perimeter: no mouth
  EXPECT_EQ(m.enclosed_fraction, 0.0);  // a line spans no volume
}

}  // namespace
}  // namespace ancfnet
