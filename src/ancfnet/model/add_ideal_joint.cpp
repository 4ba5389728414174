// ModelBuilder::AddIdealJoint (model/model_builder.hpp): resolves and checks an ideal joint's
// sides, its point and its axis.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/joint_anchor_resolution.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// Distance below which the two sides of a joint coincide at t = 0, relative to their distance
// from the origin (or 1 m).
constexpr double kCoincidenceTolerance = 1e-9;
// Angle (rad) within which a cable-point revolute joint's axis is along the cable's tangent.
constexpr double kParallelTolerance = 1e-6;

bool IsFrame(const JointAnchor& anchor) { return anchor.kind != JointAnchor::Kind::kPoint; }

// R_WB at t = 0 of a body side; the identity for the ground.
Matrix3d InitialFrame(const Model& model, const JointAnchor& anchor) {
  if (anchor.kind == JointAnchor::Kind::kBody)
    return model.rigid_bodies()[anchor.body].initial_orientation;
  return Matrix3d::Identity();
}

// The slope r' at t = 0 of a cable point.
Vector3d InitialSlope(const Model& model, const JointAnchor& anchor) {
  Vector3d slope = Vector3d::Zero();
  for (int k = 0; k < anchor.num_blocks; ++k)
    slope += anchor.slope_weight[k] * model.initial_positions().segment<3>(anchor.dof[k]);
  return slope;
}

const char* TypeName(IdealJoint::Type type) {
  switch (type) {
    case IdealJoint::Type::kSpherical:
      return "spherical";
    case IdealJoint::Type::kRevolute:
      return "revolute";
    case IdealJoint::Type::kWeld:
      return "weld";
    case IdealJoint::Type::kLine:
      return "line";
    case IdealJoint::Type::kPrismatic:
      return "prismatic";
  }
  return "";
}

}  // namespace

void ModelBuilder::CheckJointNameIsFree(const std::string& name) const {
  bool taken = false;
  for (const ClearanceJoint& joint : model_.clearance_joints_) taken = taken || joint.name == name;
  for (const IdealJoint& joint : model_.ideal_joints_) taken = taken || joint.name == name;
  if (taken) throw InputError(fmt::format("two joints are named '{}'", name));
}

void ModelBuilder::AddIdealJoint(const IdealJointSpec& spec) {
  if (spec.name.empty()) throw InputError("a joint needs a non-empty name");
  CheckJointNameIsFree(spec.name);
  if (spec.first.kind == JointAnchor::Kind::kGround &&
      spec.second.kind == JointAnchor::Kind::kGround)
    throw InputError("a joint cannot join the ground to itself");
  if (spec.point && !spec.point->allFinite()) throw InputError("the joint's point must be finite");
  if (!spec.axis.allFinite() || !(spec.axis.norm() > 0.0))
    throw InputError("the joint axis must be a finite, non-zero vector");
  // A body side without a point of its own takes the joint's point.
  JointAnchorSpec first_spec = spec.first;
  JointAnchorSpec second_spec = spec.second;
  for (JointAnchorSpec* side : {&first_spec, &second_spec})
    if (!side->position && spec.point) side->position = spec.point;
  IdealJoint joint{.name = spec.name,
                   .type = spec.type,
                   .first = ResolveJointAnchor(model_, first_spec, "first"),
                   .second = ResolveJointAnchor(model_, second_spec, "second")};
  // A body or the ground without any point sits at the other side's centre (a cable point's or
  // a point mass's), or, for two bodies, at the second's centre of mass.
  for (auto [anchor, given, other, other_given] :
       {std::tuple{&joint.first, &first_spec, &joint.second, &second_spec},
        std::tuple{&joint.second, &second_spec, &joint.first, &first_spec}}) {
    if (given->position) {
      if (anchor->kind == JointAnchor::Kind::kGround) anchor->ground_point = *given->position;
      continue;
    }
    if (anchor->kind == JointAnchor::Kind::kPoint) continue;
    const Vector3d center = CalcInitialAnchorCenter(model_, *other);
    if (anchor->kind == JointAnchor::Kind::kGround) {
      anchor->ground_point = center;
    } else if (other->kind == JointAnchor::Kind::kPoint || other_given->position) {
      const RigidBody& body = model_.rigid_bodies()[anchor->body];
      anchor->body_point =
          body.initial_orientation.transpose() *
          (center - model_.initial_positions().segment<3>(body.position_dof()));
    }
  }
  const char* type = TypeName(spec.type);
  // A revolute joint may also turn about a cable's tangent: its first side a cable point.
  const bool first_turns = IsFrame(joint.first) ||
                           (spec.type == IdealJoint::Type::kRevolute && joint.first.has_slope);
  const bool turns_with_its_sides =
      spec.type == IdealJoint::Type::kRevolute || spec.type == IdealJoint::Type::kPrismatic;
  if (turns_with_its_sides && !(first_turns && IsFrame(joint.second)))
    throw InputError(fmt::format(
        "a {} joint's axis is fixed in its sides: each side must be the ground or a body (a "
        "revolute joint's first side may also be a cable point, turning about its tangent), not "
        "a point mass{}",
        type, spec.type == IdealJoint::Type::kPrismatic ? " or cable point" : ""));
  if (spec.type == IdealJoint::Type::kLine && !IsFrame(joint.second))
    throw InputError(fmt::format(
        "second: the line of a {} joint is fixed in its second side, which must be the ground or "
        "a body",
        type));
  if (spec.type == IdealJoint::Type::kWeld &&
      !(joint.first.has_slope && IsFrame(joint.second)))
    throw InputError(
        "a weld joint fixes a cable point (first) to the ground or a body (second)");

  if (spec.type == IdealJoint::Type::kRevolute && joint.first.has_slope) {
    const Vector3d tangent = InitialSlope(model_, joint.first).normalized();
    if (spec.axis.normalized().cross(tangent).norm() > kParallelTolerance)
      throw InputError(fmt::format(
          "a revolute joint on a cable point turns about the cable's tangent: give `axis` along "
          "it, [{:.6g}, {:.6g}, {:.6g}]",
          tangent.x(), tangent.y(), tangent.z()));
  }
  const Vector3d c1 = CalcInitialAnchorCenter(model_, joint.first);
  const Vector3d c2 = CalcInitialAnchorCenter(model_, joint.second);
  const Vector3d axis = spec.axis.normalized();
  const Matrix3d r1 = InitialFrame(model_, joint.first);
  const Matrix3d r2 = InitialFrame(model_, joint.second);
  const Vector3d normal1 = axis.unitOrthogonal();
  const Vector3d normal2 = axis.cross(normal1);
  joint.axis_in_first = r1.transpose() * axis;
  joint.normal1_in_first = r1.transpose() * normal1;
  joint.normal1_in_second = r2.transpose() * normal1;
  joint.normal2_in_second = r2.transpose() * normal2;
  Vector3d gap = c1 - c2;
  const bool on_a_line =
      spec.type == IdealJoint::Type::kLine || spec.type == IdealJoint::Type::kPrismatic;
  if (on_a_line) gap -= gap.dot(axis) * axis;
  const double tolerance = kCoincidenceTolerance * std::max({1.0, c1.norm(), c2.norm()});
  if (gap.norm() > tolerance)
    throw InputError(fmt::format(
        "the two sides of {} joint '{}' are {:.6g} m apart at t = 0 ({}); give the joint's "
        "`point` or the sides' points so that they meet",
        type, spec.name, gap.norm(),
        on_a_line ? "from the line" : "between their points"));
  if (spec.type == IdealJoint::Type::kWeld)
    joint.slope_in_second = r2.transpose() * InitialSlope(model_, joint.first);
  model_.ideal_joints_.push_back(joint);
}

}  // namespace ancfnet
