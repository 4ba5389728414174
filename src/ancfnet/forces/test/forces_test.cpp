#include "ancfnet/forces/forces.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

// Two cables, clamped and pinned, with damping, a point force, a moment and a distributed load.
Model MakeLoadedModel() {
  Material material{.youngs_modulus = 1.0e8,
                    .density = 1200.0,
                    .axial_damping_time = 0.01,
                    .bending_damping_time = 0.02};
  const CableProperties properties = MakeCableProperties(material, MakeCircleSection(0.02));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({"a", Vector3d::Zero(), Vector3d(1.0, 0.0, 0.0), 3, properties});
  builder.AddCable({"b", Vector3d(0.0, 1.0, 0.0), Vector3d(0.0, 1.0, 1.0), 2, properties});
  builder.AddClamp({"a", 0.0});
  builder.AddPin({"b", 0.0});
  builder.AddPointForce({"a", 0.7}, Vector3d(1.0, -2.0, 3.0));
  builder.AddPointMoment({"a", 1.0}, Vector3d(0.5, 4.0, -1.0));
  builder.AddDistributedLoad("b", Vector3d(0.3, 0.0, 0.1));
  return builder.Build();
}

// Point masses, an ideal knot and spring-damper links of every kind of point pair: cable point
// to point mass (hardening law, stiffness-proportional damping), point mass to cable end with
// zero natural length (isotropic damping), and cable point to cable point (tension-only table).
Model MakeLinkedModel(bool orbital_frame = false) {
  const CableProperties properties = MakeCableProperties(
      {.youngs_modulus = 1.0e8, .density = 1200.0}, MakeCircleSection(0.02));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  if (orbital_frame) builder.SetOrbitalFrame(0.7);  // large n: the terms must not vanish
  builder.AddPointMass("knot", 0.3, Vector3d(1.0, 0.0, 0.0), Vector3d(0.1, 0.2, 0.0));
  builder.AddPointMass("bullet", 0.2, Vector3d(1.5, 0.5, 0.2));
  builder.AddCable({.name = "a", .start = Vector3d::Zero(), .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2, .properties = properties, .end_knot = "knot"});
  builder.AddCable({.name = "b", .start = Vector3d(1.0, 0.0, 0.0), .end = Vector3d(1.0, 1.0, 0.0),
                    .num_elements = 2, .properties = properties, .start_knot = "knot"});
  builder.AddCable({.name = "c", .start = Vector3d(0.0, 1.0, 0.0), .end = Vector3d(1.5, 0.5, 0.2),
                    .num_elements = 1, .properties = properties});
  builder.AddPin({"a", 0.0});
  builder.AddPin({"c", 0.0});
  builder.AddSpringDamper("hardening", {"a", 0.3}, {"bullet"},
                          WithStiffnessProportionalDamping(MakePolynomialLaw(50.0, 400.0), 0.02));
  builder.AddSpringDamper("knot_link", {"bullet"}, {"c", 1.0},
                          WithConstantDamping(MakeLinearLaw(80.0), 0.5), 0.0);
  builder.AddSpringDamper("rope", {"b", 0.5}, {"c", 0.4},
                          MakePiecewiseLinearLaw({{0.0, 0.0}, {0.01, 2.0}, {0.5, 30.0}}), 0.3);
  return builder.Build();
}

// Free and fixed rigid bodies, turned, with attachments to a cable point (through the Hermite
// weights), to a point mass, and from a point mass to the fixed body, and a gyroscopic spin.
Model MakeBodyModel(bool orbital_frame = false) {
  const CableProperties properties =
      MakeCableProperties({.youngs_modulus = 1.0e8, .density = 1200.0}, MakeCircleSection(0.02));
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "a",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2,
                    .properties = properties});
  builder.AddPointMass("bullet", 0.2, Vector3d(1.5, 0.5, 0.2));
  builder.AddRigidBody(
      {.name = "target",
       .mass = 4.0,
       .inertia = Vector3d(0.5, 0.7, 0.9).asDiagonal(),
       .position = Vector3d(1.2, 0.3, -0.1),
       .orientation = Matrix3d(Eigen::AngleAxisd(0.6, Vector3d(1, 2, 3).normalized())),
       .angular_velocity = Vector3d(0.4, -1.1, 2.0)});
  builder.AddRigidBody({.name = "hub",
                        .mass = 1.0,
                        .inertia = Matrix3d::Identity(),
                        .position = Vector3d(-0.5, 0.0, 0.0),
                        .motion = BodyMotion::kFixed});
  builder.AddBodyAttachment({.name = "cable_to_target",
                             .body = "target",
                             .point = {"a", 0.7},
                             .body_point = Vector3d(0.1, -0.3, 0.2),
                             .stiffness = 300.0,
                             .damping = 2.0});
  builder.AddBodyAttachment({.name = "bullet_to_target",
                             .body = "target",
                             .point = {"bullet"},
                             .stiffness = 120.0,
                             .damping = 0.7});
  builder.AddBodyAttachment({.name = "cable_to_hub",
                             .body = "hub",
                             .point = {"a", 0.0},
                             .stiffness = 500.0,
                             .damping = 1.0});
  // Large n: the gravity-gradient and frame-rate terms of the tumbling target must not vanish.
  if (orbital_frame) builder.SetOrbitalFrame(1.3);
  return builder.Build();
}

// A mixed mesh: two cable elements (with Kelvin–Voigt damping), then two beam elements sharing
// the cable's end node, with gravity, a point force and a distributed load on the beam and a
// moment on its end node; in a fast-turning orbital frame when asked (n = 30 rad/s: n² ρI of the
// sections' rotary inertia is not lost in the elastic stiffness).
Model MakeBeamModel(bool orbital_frame = false) {
  const CableProperties properties =
      MakeCableProperties({.youngs_modulus = 1.0e8, .density = 1200.0}, MakeCircleSection(0.02));
  CableProperties damped = properties;
  damped.axial_damping_time = 0.01;
  damped.bending_damping_time = 0.02;
  const BeamCableSpec beam{
      .material = {.youngs_modulus = 1.0e8, .poisson_ratio = 0.3, .density = 1200.0},
      .section = MakeCircleBeamSection(0.02, 0.3),
      .orientation = Vector3d(0.0, 0.3, 1.0)};
  ModelBuilder builder;
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "a", .start = Vector3d::Zero(), .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2, .properties = damped});
  builder.AddCable({.name = "b", .start = Vector3d(1.0, 0.0, 0.0), .end = Vector3d(2.0, 0.0, 0.0),
                    .num_elements = 2, .properties = properties, .beam = beam,
                    .start_cable = "a"});
  // A third beam at an angle, its section held to b's end by a section lock (a knot).
  builder.AddCable({.name = "c",
                    .start = Vector3d(2.0, 0.0, 0.0),
                    .end = Vector3d(2.5, 1.0, 0.2),
                    .num_elements = 1,
                    .properties = properties,
                    .beam = BeamCableSpec{beam.material, beam.section, Vector3d(1.0, 0.0, 1.0)}});
  builder.AddSectionLock("lock", {"b", 1.0}, {"c", 0.0}, 1.0e3);
  builder.AddClamp({"a", 0.0});
  builder.AddPointForce({"b", 0.3}, Vector3d(1.0, -2.0, 3.0));
  builder.AddPointMoment({"b", 1.0}, Vector3d(0.5, 4.0, -1.0));
  builder.AddDistributedLoad("b", Vector3d(0.3, 0.0, 0.1));
  if (orbital_frame) builder.SetOrbitalFrame(30.0);
  return builder.Build();
}

// A perturbed configuration and velocity so that every term is active. Rotation increments ψ of
// bodies stay 0, where the iteration matrix's tangent operator T(ψ) = I is exact.
State MakePerturbedState(const Model& model) {
  State state = MakeInitialState(model);
  std::vector<bool> rotation(model.num_dofs(), false);
  for (const RigidBody& body : model.rigid_bodies())
    for (int k = 0; k < 3; ++k) rotation[body.rotation_dof() + k] = true;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) continue;
    if (!rotation[i]) state.q[i] += 0.05 * std::sin(1.3 * i + 0.2);
    state.v[i] = 0.4 * std::cos(0.7 * i);
  }
  return state;
}

VectorXd Residual(const Model& model, const VectorXd& q, const VectorXd& v, double load_factor,
                  Workspace& ws, const DofMap& dofs) {
  CalcInternalForces(model, q, v, ws);
  CalcExternalForces(model, q, load_factor, ws);
  VectorXd r;
  dofs.Restrict(ws.internal_force - ws.external_force, &r);
  return r;
}

void ExpectIterationMatrixMatchesFiniteDifferences(const Model& model) {
  const State state = MakePerturbedState(model);
  Workspace ws(model);
  const DofMap dofs = DofMap::FreeCoordinates(model);
  SystemMatrix matrix(model, dofs);
  const double load_factor = 0.8;
  for (const IterationWeights weights : {IterationWeights{.mass = 0.0, .damping = 0.0, .stiffness = 1.0},
                                         IterationWeights{.mass = 0.0, .damping = 1.0, .stiffness = 0.0}}) {
    AssembleIterationMatrix(model, state.q, state.v, weights, load_factor, ws, &matrix);
    const MatrixXd analytic = MatrixXd(matrix.matrix());
    MatrixXd numeric(dofs.num_unknowns(), dofs.num_unknowns());
    // Velocities enter only the (small) damping forces: a larger step keeps the round-off of
    // the large elastic forces out of the difference quotient.
    const double h = weights.stiffness != 0.0 ? 1e-7 : 1e-4;
    for (Index j = 0; j < dofs.num_unknowns(); ++j) {
      VectorXd qp = state.q, qm = state.q, vp = state.v, vm = state.v;
      const Index c = dofs.coordinates()[j];
      (weights.stiffness != 0.0 ? qp : vp)[c] += h;
      (weights.stiffness != 0.0 ? qm : vm)[c] -= h;
      numeric.col(j) = (Residual(model, qp, vp, load_factor, ws, dofs) -
                        Residual(model, qm, vm, load_factor, ws, dofs)) / (2 * h);
    }
    EXPECT_LT((analytic - numeric).norm(), 1e-6 * analytic.norm())
        << "weights k=" << weights.stiffness << " c=" << weights.damping;
  }
}

TEST(Assembly, IterationMatrixMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeLoadedModel());
}

TEST(Assembly, IterationMatrixWithLinksAndPointMassesMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeLinkedModel());
}

TEST(Assembly, IterationMatrixInAnOrbitalFrameMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeLinkedModel(/*orbital_frame=*/true));
}

TEST(Assembly, IterationMatrixWithRigidBodiesMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeBodyModel());
}

TEST(Assembly, IterationMatrixWithRigidBodiesInAnOrbitalFrameMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeBodyModel(/*orbital_frame=*/true));
}

TEST(Assembly, IterationMatrixWithBeamsMatchesFiniteDifferences) {
  const Model model = MakeBeamModel();
  ASSERT_EQ(model.beam_elements().size(), 3u);
  ASSERT_EQ(model.section_locks().size(), 1u);
  ExpectIterationMatrixMatchesFiniteDifferences(model);
}

TEST(Assembly, IterationMatrixWithBeamsInAnOrbitalFrameMatchesFiniteDifferences) {
  ExpectIterationMatrixMatchesFiniteDifferences(MakeBeamModel(/*orbital_frame=*/true));
}

TEST(Assembly, MomentOnABeamNodeDoesItsWorkOnARigidRotation) {
  // Q·δe = M·δθ for δe = δθ × a, a = r_x, d₂, d₃ (docs/theory.md, "Point moment on a beam node").
  const Model model = MakeBeamModel();
  Workspace ws(model);
  CalcExternalForces(model, model.initial_positions(), 1.0, ws);
  VectorXd moment_force = ws.applied_force - ws.distributed_force;
  const Cable& beam = model.cables()[model.FindCable("b")];
  const CableNode& tip = model.nodes()[beam.first_node + beam.num_elements];
  const Vector3d rotation(0.2, -0.7, 0.4);
  double work = 0.0;
  for (const Index dof : {tip.slope_dof, tip.section_dof, tip.section_dof + 3})
    work += moment_force.segment<3>(dof).dot(
        rotation.cross(Vector3d(model.initial_positions().segment<3>(dof))));
  EXPECT_NEAR(work, Vector3d(0.5, 4.0, -1.0).dot(rotation), 1e-12);
}

TEST(Assembly, BodyMassBlocksAreMassAndInertia) {
  const Model model = MakeBodyModel();
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix mass(model, all);
  const Workspace ws(model);
  AssembleMassMatrix(model, ws, &mass);
  const MatrixXd m(mass.matrix());
  const RigidBody& body = model.rigid_bodies()[0];
  EXPECT_LT(
      (m.block<3, 3>(body.position_dof(), body.position_dof()) - 4.0 * Matrix3d::Identity()).norm(),
      1e-15);
  EXPECT_LT((m.block<3, 3>(body.rotation_dof(), body.rotation_dof()) - body.inertia).norm(), 1e-15);
  const double coupling = m.block<3, 3>(body.position_dof(), body.rotation_dof()).norm();
  EXPECT_EQ(coupling, 0.0);
}

TEST(Assembly, InternalForcesOfIterationMatrixMatchForceOnlyPath) {
  for (const Model& model : {MakeLoadedModel(), MakeLinkedModel(), MakeLinkedModel(true),
                             MakeBodyModel(), MakeBeamModel(), MakeBeamModel(true)}) {
    const State state = MakePerturbedState(model);
    Workspace ws(model);
    const DofMap dofs = DofMap::FreeCoordinates(model);
    SystemMatrix matrix(model, dofs);
    AssembleIterationMatrix(model, state.q, state.v, {.stiffness = 1.0}, 1.0, ws, &matrix);
    const VectorXd from_matrix = ws.internal_force;
    CalcInternalForces(model, state.q, state.v, ws);
    EXPECT_LT((from_matrix - ws.internal_force).norm(), 1e-12 * ws.internal_force.norm());
  }
}

TEST(Assembly, GravityForceSumsToWeight) {
  const Model model = MakeLoadedModel();
  Workspace ws(model);
  double fz = 0.0;
  for (Index node = 0; node < model.num_nodes(); ++node) fz += ws.gravity_force[model.NodePositionDof(node) + 2];
  EXPECT_NEAR(fz, -9.81 * model.total_mass(), 1e-12);
}

}  // namespace
}  // namespace ancfnet
