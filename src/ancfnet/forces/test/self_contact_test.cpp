// Self-contact forces: two crossing cables pressed into each other (capsule chains, so slopes
// take part) and a bead (point-mass sphere) on a thread. The forces are the exact gradient of the
// contact energy (the closest points are stationary), and both Jacobians match central
// differences (the closest points moving with the coordinates), without friction and with the
// tanh and the LuGre laws, the threads also sliding over each other.

#include "ancfnet/forces/self_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

constexpr double kRadius = 0.002;

// With `beams`, both threads are ANCF beams (element: ancf_beam) with the same centre lines.
Model MakeCrossingCables(const std::optional<FrictionLaw>& friction, bool damping,
                         bool beams = false) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  const CableProperties p = MakeCableProperties(nylon, MakeCircleSection(2 * kRadius));
  std::optional<BeamCableSpec> beam;
  if (beams)
    beam = BeamCableSpec{.material = {.youngs_modulus = 3e9, .poisson_ratio = 0.4, .density = 1140},
                         .section = MakeCircleBeamSection(2 * kRadius, 0.4),
                         .orientation = Vector3d::UnitZ()};
  ModelBuilder builder;
  builder.AddCable({.name = "a",
                    .start = Vector3d(-0.1, 0.013, 0.001),
                    .end = Vector3d(0.1, -0.011, -0.0015),
                    .num_elements = 2,
                    .properties = p,
                    .beam = beam});
  // Penetrating a by about 0.3 mm where they cross.
  builder.AddCable({.name = "b",
                    .start = Vector3d(0.017, -0.1, 2 * kRadius - 0.0003),
                    .end = Vector3d(-0.009, 0.1, 2 * kRadius - 0.0004),
                    .num_elements = 2,
                    .properties = p,
                    .beam = beam});
  // A bead pressed 0.2 mm into a from above.
  builder.AddPointMass("bead", 0.01, Vector3d(0.05, -0.005, -0.000875 + 2 * kRadius - 0.0002));
  ContactSpec spec;
  spec.normal = damping ? MakeDissipativeContactLaw(NormalLawKind::kCarvalhoMartins, 1e5, 0.4)
                        : MakeHertzContactLaw(1e7);
  spec.friction = friction;
  spec.self_contact = true;
  spec.capsules_per_element = 3;
  spec.point_mass_radius = kRadius;
  builder.SetContact(spec);
  return builder.Build();
}

struct Fixture {
  // `bristle` (if not zero): the LuGre deflection every pair starts the step with. `sliding`:
  // thread a slides along x at 5 cm/s and thread b along −y at 4 cm/s over each other.
  explicit Fixture(const Model& m, const Vector3d& bristle = Vector3d::Zero(), bool sliding = false)
      : model(m), contact(m), state(MakeInitialState(m)) {
    // v = 0.01 sin(1.7 i + 0.3) over the cables' (r, r') and the bead in the order of a model
    // of cables (i is then the coordinate's index); a beam's section gradients stay at rest, so a
    // model of beams moves its centre lines as the model of cables does.
    const auto rate = [](Index i) { return 0.01 * std::sin(1.7 * static_cast<double>(i) + 0.3); };
    for (Index n = 0; n < m.num_nodes(); ++n)
      for (int k = 0; k < 3; ++k) {
        state.v[m.nodes()[n].position_dof + k] = rate(6 * n + k);
        state.v[m.nodes()[n].slope_dof + k] = rate(6 * n + 3 + k);
      }
    for (std::size_t p = 0; p < m.point_masses().size(); ++p)
      for (int k = 0; k < 3; ++k)
        state.v[m.point_masses()[p].dof + k] = rate(6 * m.num_nodes() + 3 * p + k);
    const Vector3d slide[2] = {Vector3d(0.05, 0.0, 0.0), Vector3d(0.0, -0.04, 0.0)};
    for (int c = 0; c < 2 && sliding; ++c) {
      const Cable& cable = model.cables()[c];
      for (Index node = cable.first_node; node <= cable.first_node + cable.num_elements; ++node)
        state.v.segment<3>(model.NodePositionDof(node)) += slide[c];
    }
    const int n = static_cast<int>(contact.primitives().size());
    if (bristle != Vector3d::Zero())
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
          state.self_contact_history.push_back({a, b, {.speed = 0.3, .bristle = bristle}});
    contact.FindCandidates(state, 1e-3);
  }
  VectorXd Forces(const VectorXd& q, const VectorXd& v, double* energy = nullptr) const {
    Workspace ws(model);
    ws.internal_force.setZero();
    ws.viscous_force.setZero();
    ws.contact_energy = 0.0;
    contact.AddForces(q, v, ws);
    if (energy) *energy = ws.contact_energy;
    return ws.internal_force;
  }
  const Model& model;
  SelfContact contact;
  State state;
};

TEST(SelfContact, ForcesAreTheGradientOfTheContactEnergy) {
  const Model model = MakeCrossingCables(std::nullopt, false);
  const Fixture f(model);
  const SelfContact::Summary s = f.contact.Summarize(f.state.q, f.state.v);
  ASSERT_EQ(s.active, 2);  // a–b and bead–a
  const VectorXd q = f.state.q;
  const VectorXd force = f.Forces(q, f.state.v);
  const double h = 1e-9;
  VectorXd gradient(q.size());
  for (Index j = 0; j < q.size(); ++j) {
    VectorXd qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    double up = 0.0, um = 0.0;
    f.Forces(qp, f.state.v, &up);
    f.Forces(qm, f.state.v, &um);
    gradient[j] = (up - um) / (2 * h);
  }
  // Q_int = ∂U/∂q.
  EXPECT_LT((force - gradient).norm(), 1e-5 * force.norm());
  // Action and reaction: no net force.
  Vector3d total = Vector3d::Zero();
  for (Index node = 0; node < model.num_nodes(); ++node)
    total += force.segment<3>(model.NodePositionDof(node));
  total += force.segment<3>(model.point_masses()[0].dof);
  EXPECT_LT(total.norm(), 1e-10 * force.norm());
}

void ExpectJacobiansMatchFiniteDifferences(const Model& model,
                                           const Vector3d& bristle = Vector3d::Zero(),
                                           bool sliding = false) {
  const Fixture f(model, bristle, sliding);
  const DofMap all = DofMap::AllCoordinates(model);
  for (const IterationWeights weights :
       {IterationWeights{.mass = 0, .damping = 0, .stiffness = 1},
        IterationWeights{.mass = 0, .damping = 1, .stiffness = 0}}) {
    SystemMatrix matrix(model, all);
    matrix.AddContactCouplings(f.contact.coupled_owners());
    matrix.SetZero();
    f.contact.AddJacobian(f.state.q, f.state.v, weights, &matrix);
    const MatrixXd analytic = MatrixXd(matrix.matrix());
    const MatrixXd fd = test::CalcCentralDifferenceJacobian(
        [&](const VectorXd& x, const VectorXd& x_dot) { return f.Forces(x, x_dot); }, f.state.q,
        f.state.v, weights.stiffness != 0.0);
    const double error = (analytic - fd).norm() / fd.norm();
    std::printf("self-contact %s Jacobian: relative error %.2e\n",
                weights.stiffness != 0.0 ? "stiffness" : "damping", error);
    EXPECT_LT(error, 1e-6);
  }
}

TEST(SelfContact, JacobiansMatchFiniteDifferences) {
  ExpectJacobiansMatchFiniteDifferences(MakeCrossingCables(std::nullopt, true));
  ExpectJacobiansMatchFiniteDifferences(
      MakeCrossingCables(MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1), true));
  // And with the LuGre bristles stepped over h = 1 ms from a deflection z₀ (re-projected onto
  // each pair's tangent plane).
  ExpectJacobiansMatchFiniteDifferences(
      MakeCrossingCables(MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1), true),
      Vector3d(2e-5, -1e-5, 1e-5));
}

// Issue 13: beam threads touch through the capsules of their centre lines, which are the cable's
// (the same Hermite in r, r_x), so two crossing beams moving as the cables do press into each
// other exactly as two crossing cables (Carvalho–Martins law, its damping included): the same
// pairs, penetration and normal force, the same forces on positions and slopes (none on the
// section gradients), and Jacobians that match central differences.
TEST(SelfContact, CrossingBeamsTouchLikeCrossingCables) {
  const Model cables = MakeCrossingCables(std::nullopt, true);
  const Model beams = MakeCrossingCables(std::nullopt, true, true);
  ASSERT_EQ(beams.beam_elements().size(), 4u);
  const Fixture fc(cables);
  const Fixture fb(beams);
  const SelfContact::Summary sc = fc.contact.Summarize(fc.state.q, fc.state.v);
  const SelfContact::Summary sb = fb.contact.Summarize(fb.state.q, fb.state.v);
  ASSERT_EQ(sb.active, 2);
  EXPECT_EQ(sb.active, sc.active);
  EXPECT_GT(sb.max_penetration, 0.2e-3);
  EXPECT_NEAR(sb.max_penetration, sc.max_penetration, 1e-12);
  EXPECT_NEAR(sb.normal_force, sc.normal_force, 1e-9 * sc.normal_force);
  const VectorXd force_c = fc.Forces(fc.state.q, fc.state.v);
  const VectorXd force_b = fb.Forces(fb.state.q, fb.state.v);
  for (Index n = 0; n < cables.num_nodes(); ++n) {
    const CableNode& c = cables.nodes()[n];
    const CableNode& b = beams.nodes()[n];
    for (const auto& [dof_c, dof_b] :
         {std::pair{c.position_dof, b.position_dof}, std::pair{c.slope_dof, b.slope_dof}})
      EXPECT_LT((force_b.segment<3>(dof_b) - force_c.segment<3>(dof_c)).norm(),
                1e-9 * force_c.norm())
          << "node " << n;
    EXPECT_EQ(force_b.segment<6>(b.section_dof).norm(), 0.0) << "node " << n;
  }
  ExpectJacobiansMatchFiniteDifferences(MakeCrossingCables(std::nullopt, true, true));
}

// (5) of issue 17: the closest points (s*, t*) move with the coordinates, and friction's tangent
// plane turns with the pair's normal; the threads slide over each other.
TEST(SelfContact, SlidingFrictionJacobiansMatchFiniteDifferences) {
  ExpectJacobiansMatchFiniteDifferences(MakeCrossingCables(std::nullopt, true), Vector3d::Zero(),
                                        true);
  ExpectJacobiansMatchFiniteDifferences(
      MakeCrossingCables(MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1), true), Vector3d::Zero(), true);
  ExpectJacobiansMatchFiniteDifferences(
      MakeCrossingCables(MakeLuGreFriction(0.4, 0.3, 1e-2, 1e4, 50.0, 0.1), true),
      Vector3d(2e-5, -1e-5, 1e-5), true);
}

// Two parallel threads 0.3 (r_a + r_b) apart: candidates (the margins add up to (r_a + r_b)/2),
// not coupled while at rest (g_c = (r_a + r_b)/4), coupled once the upper one comes down at
// 0.2 m/s (g_c grows by 2 h · 0.2 m/s = 0.4 mm).
TEST(SelfContact, CouplesOnlyThePairsThatTouchOrNearlyTouch) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  const CableProperties p = MakeCableProperties(nylon, MakeCircleSection(2 * kRadius));
  const double gap = 0.3 * 2 * kRadius;
  ModelBuilder builder;
  builder.AddCable({.name = "a",
                    .start = Vector3d(0, 0, 0),
                    .end = Vector3d(0.1, 0, 0),
                    .num_elements = 2,
                    .properties = p});
  builder.AddCable({.name = "b",
                    .start = Vector3d(0, 0, 2 * kRadius + gap),
                    .end = Vector3d(0.1, 0, 2 * kRadius + gap),
                    .num_elements = 2,
                    .properties = p});
  ContactSpec spec;
  spec.normal = MakeHertzContactLaw(1e7);
  spec.self_contact = true;
  spec.capsules_per_element = 3;
  builder.SetContact(spec);
  const Model model = builder.Build();
  SelfContact contact(model);
  State state = MakeInitialState(model);
  contact.FindCandidates(state, 1e-3);
  EXPECT_GT(contact.num_candidates(), 0);
  EXPECT_TRUE(contact.coupled_owners().empty());
  EXPECT_TRUE(contact.near_owners().empty());
  for (Index node = 0; node < model.num_nodes(); ++node) {
    const Index dof = model.NodePositionDof(node);
    if (state.q[dof + 2] > kRadius) state.v[dof + 2] = -0.2;
  }
  contact.FindCandidates(state, 1e-3);
  EXPECT_FALSE(contact.coupled_owners().empty());
  EXPECT_EQ(contact.near_owners(), contact.coupled_owners());
  for (const auto& [a, b] : contact.coupled_owners()) EXPECT_NE(a < 2, b < 2);  // a's with b's
}

// A step of the energy-consistent midpoint rule (SetStep) in which thread b and the bead start
// 0.5 mm above thread a, are apart from it at the midpoint and press into it at the end: the
// pairs' forces are the discrete gradients over the step, which the end of the step, moving
// twice as far as the midpoint, sets. Their Jacobian with respect to the midpoint must be there
// (without it Newton cycled as the end touched at one iterate and not at the next, issue 17),
// and it matches central differences up to the turning of the direction n̄ of the discrete
// gradient, which it leaves out.
TEST(SelfContact, StepJacobianWhereOnlyTheEndOfTheStepTouchesMatchesFiniteDifferences) {
  const Model model = MakeCrossingCables(std::nullopt, false);
  SelfContact contact(model);
  const VectorXd q_end = MakeInitialState(model).q;
  State start = MakeInitialState(model);
  const auto lift = [&](Index dof) { start.q[dof + 2] += 0.0008; };
  const Cable& b = model.cables()[1];
  for (Index node = b.first_node; node <= b.first_node + b.num_elements; ++node)
    lift(model.NodePositionDof(node));
  lift(model.point_masses()[0].dof);
  contact.FindCandidates(start, 1e-3);
  ASSERT_FALSE(contact.coupled_owners().empty());
  VectorXd end = q_end;
  contact.SetStep(start.q, &end);
  const VectorXd mid = 0.5 * (start.q + q_end);
  const VectorXd v = VectorXd::Zero(model.num_dofs());
  const auto forces = [&](const VectorXd& q, const VectorXd& /*v*/) {
    end = 2.0 * q - start.q;  // e₁ = 2 e_m − e₀
    Workspace ws(model);
    ws.internal_force.setZero();
    ws.viscous_force.setZero();
    contact.AddForces(q, v, ws);
    return VectorXd(ws.internal_force);
  };
  ASSERT_GT(forces(mid, v).norm(), 1.0);  // the end of the step touches
  const MatrixXd fd = test::CalcCentralDifferenceJacobian(forces, mid, v, true, 1e-9);
  end = 2.0 * mid - start.q;
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix matrix(model, all);
  matrix.AddContactCouplings(contact.coupled_owners());
  matrix.SetZero();
  contact.AddJacobian(mid, v, {.mass = 0, .damping = 0, .stiffness = 1}, &matrix);
  const double error = (MatrixXd(matrix.matrix()) - fd).norm() / fd.norm();
  std::printf("self-contact step Jacobian, apart at the midpoint: relative error %.2e\n", error);
  EXPECT_LT(error, 0.05);
}

// Without its contact coupling a touching pair adds only each primitive's blocks with itself:
// the full Jacobian on the entries of the uncoupled pattern (the owners' own groups; a and b and
// the bead share no element), nothing elsewhere.
TEST(SelfContact, PairWithoutCouplingAddsOnlyItsOwnBlocks) {
  const Model model = MakeCrossingCables(MakeTanhFriction(0.4, 0.3, 1e-2, 1e-1), true);
  const Fixture f(model);
  const DofMap all = DofMap::AllCoordinates(model);
  const IterationWeights weights{.mass = 0, .damping = 0.7, .stiffness = 1};
  SystemMatrix coupled(model, all), uncoupled(model, all);
  coupled.AddContactCouplings(f.contact.coupled_owners());
  coupled.SetZero();
  uncoupled.SetZero();
  f.contact.AddJacobian(f.state.q, f.state.v, weights, &coupled);
  f.contact.AddJacobian(f.state.q, f.state.v, weights, &uncoupled);
  const MatrixXd full = MatrixXd(coupled.matrix());
  MatrixXd own = MatrixXd::Zero(full.rows(), full.cols());
  const SparseMatrixd& pattern = uncoupled.matrix();
  for (int j = 0; j < pattern.outerSize(); ++j)
    for (SparseMatrixd::InnerIterator it(pattern, j); it; ++it)
      own(it.row(), it.col()) = full(it.row(), it.col());
  ASSERT_GT(own.norm(), 0.0);
  EXPECT_LT((MatrixXd(uncoupled.matrix()) - own).norm(), 1e-12 * own.norm());
  EXPECT_GT((full - own).norm(), 0.1 * own.norm());  // the blocks between the owners left out
}

TEST(SelfContactFilter, LeavesOutNeighboursOnAThreadAndAtAKnot) {
  Material nylon{.youngs_modulus = 3e9, .density = 1140};
  const CableProperties p = MakeCableProperties(nylon, MakeCircleSection(2 * kRadius));
  ModelBuilder builder;
  builder.AddPointMass("knot", 0.0, Vector3d::Zero());
  builder.AddCable({.name = "a",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(0.1, 0, 0),
                    .num_elements = 4,
                    .properties = p,
                    .start_knot = "knot"});
  builder.AddCable({.name = "b",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(0, 0.1, 0),
                    .num_elements = 4,
                    .properties = p,
                    .start_knot = "knot"});
  builder.AddCable({.name = "c",
                    .start = Vector3d(0.05, -0.05, 0),
                    .end = Vector3d(0.05, 0.05, 0),
                    .num_elements = 4,
                    .properties = p});
  ContactSpec spec;
  spec.normal = MakeHertzContactLaw(1e7);
  spec.self_contact = true;
  spec.capsules_per_element = 8;  // 3.125 mm capsules; reach 2 (r + r) = 8 mm
  spec.point_mass_radius = kRadius;
  builder.SetContact(spec);
  const Model model = builder.Build();
  const auto primitives = MakeSelfContactPrimitives(model);
  ASSERT_EQ(primitives.size(), 3u * 32u + 1u);
  const SelfContactFilter filter(model, primitives);
  // On a: capsule 0 and 1 and 3 (6.25 mm away along it) are neighbours; 0 and 4 (9.4 mm) not.
  EXPECT_TRUE(filter.Excluded(0, 1));
  EXPECT_TRUE(filter.Excluded(0, 3));
  EXPECT_FALSE(filter.Excluded(0, 4));
  // Across the knot: the capsules of the two elements that meet there (a's and b's first
  // elements, capsules 0 … 7) are left out; a's second element and b's first are kept.
  const int b = 32, c = 64, knot = 96;
  EXPECT_TRUE(filter.Excluded(0, b));
  EXPECT_TRUE(filter.Excluded(7, b + 7));
  EXPECT_FALSE(filter.Excluded(8, b + 1));
  // The knot sphere and the elements it holds; c is unrelated.
  EXPECT_TRUE(filter.Excluded(0, knot));
  EXPECT_TRUE(filter.Excluded(b, knot));
  EXPECT_TRUE(filter.Excluded(4, knot));
  EXPECT_FALSE(filter.Excluded(8, knot));
  EXPECT_FALSE(filter.Excluded(c, knot));
  EXPECT_FALSE(filter.Excluded(0, c));
}

}  // namespace
}  // namespace ancfnet
