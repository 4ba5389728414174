// The constraint equations of ideal joints between every kind of side (ground, spinning rigid
// bodies, ANCF cable points): the Jacobian G against central differences of g, the geometric
// stiffness ∂(Gᵀλ)/∂q against differences of Gᵀλ, the convective term Ġv against differences of
// G v along v, and the bordered matrix's layout.

#include <gtest/gtest.h>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/forces/test/central_difference_jacobian.hpp"
#include "ancfnet/forces/test/spinning_body.hpp"
#include "ancfnet/forces/test/target_contact_check.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

using Kind = JointAnchor::Kind;
using Type = IdealJoint::Type;

const Vector3d kRopeEnd(0.3, 0.1, 0.05);
const Vector3d kJointPoint = 0.3 * kRopeEnd;  // the rope's point at s = 0.3

struct Case {
  const char* label;
  Type type;
  Kind first;
  Kind second;
};

// A rope and, as the case asks, bodies "a" (first) and "b" (second) near the joint's point.
Model MakeModel(const Case& c) {
  ModelBuilder builder;
  test::AddTestRope(Vector3d::Zero(), kRopeEnd, &builder);
  builder.SetInitialVelocity("rope", Vector3d(0.01, 0.02, -0.01), Vector3d(1.0, -2.0, 3.0));
  // A revolute joint on the rope turns about its tangent.
  const bool about_the_rope = c.type == Type::kRevolute && c.first == Kind::kPoint;
  IdealJointSpec spec{
      .name = "joint", .type = c.type, .axis = about_the_rope ? kRopeEnd : Vector3d(1, -2, 2)};
  auto side = [&](Kind kind, const char* body, double angle) -> JointAnchorSpec {
    if (kind == Kind::kBody) {
      test::AddSpinningBody(body, kJointPoint + Vector3d(0.02, -0.01, 0.03), angle, &builder);
      return {.kind = Kind::kBody, .name = body, .position = kJointPoint};
    }
    if (kind == Kind::kPoint) return {.kind = Kind::kPoint, .name = "rope", .s = 0.3};
    return {.kind = Kind::kGround, .position = kJointPoint};
  };
  spec.first = side(c.first, "a", 0.4);
  spec.second = side(c.second, "b", -0.7);
  builder.AddIdealJoint(spec);
  return builder.Build();
}

// The state moved away from the joint's initial configuration, so that g ≠ 0 and every term
// of the derivatives counts; ψ stays 0 (the reference rotations carry the orientation).
State MakeTestState(const Model& model) {
  State state = MakeInitialState(model);
  for (Index i = 0; i < state.q.size(); ++i) state.q[i] += 1e-3 * std::sin(1.7 * i + 0.3);
  for (const RigidBody& body : model.rigid_bodies())
    state.q.segment<3>(body.rotation_dof()).setZero();
  return state;
}

MatrixXd DenseJacobian(const JointConstraints& constraints, Index num_dofs) {
  MatrixXd g = MatrixXd::Zero(constraints.size(), num_dofs);
  for (Index i = 0; i < constraints.size(); ++i)
    for (int k = 0; k < constraints.NumBlocks(i); ++k)
      g.block<1, 3>(i, constraints.BlockDof(i, k)) += constraints.Gradient(i, k).transpose();
  return g;
}

void ExpectDerivativesMatch(const Case& c) {
  SCOPED_TRACE(c.label);
  const Model model = MakeModel(c);
  const State state = MakeTestState(model);
  const Index n = model.num_dofs();
  JointConstraints constraints(model);
  ASSERT_EQ(constraints.size(), model.ideal_joints()[0].num_equations());
  auto violation = [&](const VectorXd& q) {
    JointConstraints at(model);
    at.Evaluate(q, state.v, state.body_rotation);
    return VectorXd(at.violation());
  };
  // G against differences of g.
  constraints.Evaluate(state.q, state.v, state.body_rotation);
  const MatrixXd g = DenseJacobian(constraints, n);
  MatrixXd g_fd(constraints.size(), n);
  const double h = 1e-7;
  for (Index j = 0; j < n; ++j) {
    VectorXd qp = state.q, qm = state.q;
    qp[j] += h;
    qm[j] -= h;
    g_fd.col(j) = (violation(qp) - violation(qm)) / (2 * h);
  }
  EXPECT_LT((g - g_fd).norm(), 1e-7 * g.norm());
  // The rate G v against differences of g along v.
  const VectorXd rate_fd = (violation(state.q + h * state.v) - violation(state.q - h * state.v)) /
                           (2 * h);
  EXPECT_LT((constraints.CalcRate(state.v) - rate_fd).norm(), 1e-6 * (1.0 + rate_fd.norm()));
  // Ġv against differences of G v along v (ψ̇ = ω_B at ψ = 0: R(ε) = R_ref exp(ε ω̃_B)).
  auto rate_at = [&](const VectorXd& q) {
    JointConstraints at(model);
    at.Evaluate(q, state.v, state.body_rotation);
    return at.CalcRate(state.v);
  };
  const VectorXd convective_fd =
      (rate_at(state.q + h * state.v) - rate_at(state.q - h * state.v)) / (2 * h);
  EXPECT_LT((constraints.convective_term() - convective_fd).norm(),
            1e-5 * (1.0 + convective_fd.norm()));
  // ∂(Gᵀλ)/∂q against differences of Gᵀλ.
  VectorXd lambda(constraints.size());
  for (Index i = 0; i < lambda.size(); ++i) lambda[i] = 3.0 * std::cos(2.3 * i + 1.0);
  const DofMap all = DofMap::AllCoordinates(model);
  SystemMatrix matrix(model, all);
  matrix.SetZero();
  constraints.AddGeometricStiffness(lambda, 1.0, &matrix);
  const MatrixXd analytic = MatrixXd(matrix.matrix());
  const MatrixXd fd = test::CalcCentralDifferenceJacobian(
      [&](const VectorXd& q, const VectorXd&) {
        JointConstraints at(model);
        at.Evaluate(q, state.v, state.body_rotation);
        VectorXd force = VectorXd::Zero(n);
        at.AddReaction(lambda, &force);
        return force;
      },
      state.q, state.v, /*positions=*/true, 1e-7);
  EXPECT_LT((analytic - fd).norm(), 1e-6 * (1.0 + fd.norm()));
  // The bordered matrix: [S Gᵀ; G 0] over the unknowns (here every coordinate).
  SparseMatrixd bordered;
  constraints.AssembleBorderedMatrix(matrix.matrix(), all, &bordered);
  const MatrixXd dense = MatrixXd(bordered);
  ASSERT_EQ(dense.rows(), n + constraints.size());
  EXPECT_EQ(dense.topLeftCorner(n, n), analytic);
  EXPECT_EQ(dense.bottomLeftCorner(constraints.size(), n), g);
  EXPECT_EQ(dense.topRightCorner(n, constraints.size()), g.transpose());
  EXPECT_EQ(dense.bottomRightCorner(constraints.size(), constraints.size()).norm(), 0.0);
}

TEST(JointConstraints, SphericalDerivativesMatchDifferences) {
  ExpectDerivativesMatch({"body-rope", Type::kSpherical, Kind::kBody, Kind::kPoint});
  ExpectDerivativesMatch({"rope-body", Type::kSpherical, Kind::kPoint, Kind::kBody});
  ExpectDerivativesMatch({"body-body", Type::kSpherical, Kind::kBody, Kind::kBody});
  ExpectDerivativesMatch({"ground-body", Type::kSpherical, Kind::kGround, Kind::kBody});
  ExpectDerivativesMatch({"rope-ground", Type::kSpherical, Kind::kPoint, Kind::kGround});
}

TEST(JointConstraints, RevoluteDerivativesMatchDifferences) {
  ExpectDerivativesMatch({"body-body", Type::kRevolute, Kind::kBody, Kind::kBody});
  ExpectDerivativesMatch({"ground-body", Type::kRevolute, Kind::kGround, Kind::kBody});
  ExpectDerivativesMatch({"body-ground", Type::kRevolute, Kind::kBody, Kind::kGround});
  ExpectDerivativesMatch({"rope-body", Type::kRevolute, Kind::kPoint, Kind::kBody});
  ExpectDerivativesMatch({"rope-ground", Type::kRevolute, Kind::kPoint, Kind::kGround});
}

TEST(JointConstraints, WeldDerivativesMatchDifferences) {
  ExpectDerivativesMatch({"rope-body", Type::kWeld, Kind::kPoint, Kind::kBody});
  ExpectDerivativesMatch({"rope-ground", Type::kWeld, Kind::kPoint, Kind::kGround});
}

TEST(JointConstraints, LineDerivativesMatchDifferences) {
  ExpectDerivativesMatch({"body-body", Type::kLine, Kind::kBody, Kind::kBody});
  ExpectDerivativesMatch({"rope-body", Type::kLine, Kind::kPoint, Kind::kBody});
  ExpectDerivativesMatch({"body-ground", Type::kLine, Kind::kBody, Kind::kGround});
}

TEST(JointConstraints, PrismaticDerivativesMatchDifferences) {
  ExpectDerivativesMatch({"body-body", Type::kPrismatic, Kind::kBody, Kind::kBody});
  ExpectDerivativesMatch({"ground-body", Type::kPrismatic, Kind::kGround, Kind::kBody});
  ExpectDerivativesMatch({"body-ground", Type::kPrismatic, Kind::kBody, Kind::kGround});
}

TEST(JointConstraints, HoldAtTheInitialState) {
  for (const Case& c : {Case{"revolute", Type::kRevolute, Kind::kBody, Kind::kBody},
                        Case{"prismatic", Type::kPrismatic, Kind::kBody, Kind::kBody},
                        Case{"revolute on the rope", Type::kRevolute, Kind::kPoint, Kind::kBody},
                        Case{"weld", Type::kWeld, Kind::kPoint, Kind::kBody},
                        Case{"line", Type::kLine, Kind::kPoint, Kind::kBody}}) {
    const Model model = MakeModel(c);
    const State state = MakeInitialState(model);
    JointConstraints constraints(model);
    constraints.Evaluate(state.q, state.v, state.body_rotation);
    EXPECT_LT(constraints.MaxViolation(), 1e-15) << c.label;
  }
}

TEST(JointConstraints, BuilderRefusesInvalidJoints) {
  ModelBuilder builder;
  test::AddTestRope(Vector3d::Zero(), kRopeEnd, &builder);
  test::AddSpinningBody("a", kJointPoint, 0.4, &builder);
  const JointAnchorSpec body{.kind = Kind::kBody, .name = "a"};
  const JointAnchorSpec rope{.kind = Kind::kPoint, .name = "rope", .s = 0.3};
  builder.AddIdealJoint({.name = "pin", .type = Type::kSpherical, .first = rope, .second = body});
  EXPECT_THROW(
      builder.AddIdealJoint({.name = "pin", .type = Type::kSpherical, .first = rope, .second = body}),
      InputError);  // a second joint named 'pin'
  EXPECT_THROW(builder.AddIdealJoint({.name = "x",
                                      .type = Type::kSpherical,
                                      .first = rope,
                                      .second = {.kind = Kind::kBody, .name = "nobody"}}),
               InputError);
  EXPECT_THROW(builder.AddIdealJoint(
                   {.name = "x", .type = Type::kRevolute, .first = body, .second = rope}),
               InputError);  // a revolute joint's second side must turn
  EXPECT_THROW(builder.AddIdealJoint({.name = "x",
                                      .type = Type::kRevolute,
                                      .first = rope,
                                      .second = body,
                                      .axis = Vector3d(0, 0, 1)}),
               InputError);  // on a cable point, about its tangent only
  EXPECT_THROW(builder.AddIdealJoint(
                   {.name = "x", .type = Type::kPrismatic, .first = body, .second = rope}),
               InputError);  // and a prismatic joint's
  EXPECT_THROW(builder.AddIdealJoint({.name = "x",
                                      .type = Type::kRevolute,
                                      .first = {.kind = Kind::kGround},
                                      .second = body,
                                      .axis = Vector3d::Zero()}),
               InputError);
  EXPECT_THROW(builder.AddIdealJoint({.name = "x",
                                      .type = Type::kSpherical,
                                      .first = {.kind = Kind::kPoint, .name = "rope", .s = 0.9},
                                      .second = {.kind = Kind::kBody,
                                                 .name = "a",
                                                 .position = kJointPoint}}),
               InputError);  // the sides are apart at t = 0
}

}  // namespace
}  // namespace ancfnet
