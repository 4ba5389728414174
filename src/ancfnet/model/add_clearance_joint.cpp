// ModelBuilder::AddClearanceJoint (model/model_builder.hpp): resolves and checks a clearance
// joint's anchors, geometry and laws.

#include <fmt/format.h>

#include <cmath>
#include <tuple>

#include "ancfnet/common/error.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

// The centre at t = 0 of a resolved anchor.
Vector3d InitialCenter(const Model& model, const JointAnchor& anchor) {
  switch (anchor.kind) {
    case JointAnchor::Kind::kGround:
      return anchor.ground_point;
    case JointAnchor::Kind::kBody: {
      const RigidBody& body = model.rigid_bodies()[anchor.body];
      return model.initial_positions().segment<3>(body.position_dof()) +
             body.initial_orientation * anchor.body_point;
    }
    case JointAnchor::Kind::kPoint:
      break;
  }
  Vector3d c = Vector3d::Zero();
  for (int k = 0; k < anchor.num_blocks; ++k)
    c += anchor.weight[k] * model.initial_positions().segment<3>(anchor.dof[k]);
  return c;
}

// A body or a point; the ground is resolved once the other side is known.
JointAnchor ResolveNamedAnchor(const Model& model, const JointAnchorSpec& spec) {
  JointAnchor anchor;
  anchor.kind = spec.kind;
  if (spec.position && !spec.position->allFinite()) throw InputError("the position must be finite");
  if (spec.kind == JointAnchor::Kind::kBody) {
    anchor.body = model.FindRigidBody(spec.name);
    if (anchor.body < 0) throw InputError(fmt::format("no rigid body named '{}'", spec.name));
    const RigidBody& body = model.rigid_bodies()[anchor.body];
    if (spec.position)
      anchor.body_point = body.initial_orientation.transpose() *
                          (*spec.position - model.initial_positions().segment<3>(body.dof));
  } else if (spec.kind == JointAnchor::Kind::kPoint) {
    const PointLocation point = model.LocatePoint(spec.name, spec.s);
    anchor.num_blocks = point.num_blocks;
    anchor.dof = point.dof;
    anchor.weight = point.weight;
    if (model.FindPointMass(spec.name) < 0) {
      const MaterialPoint material = model.LocateCablePoint(model.FindCable(spec.name), spec.s);
      const HermiteShape shape =
          CalcHermiteShape(material.xi, model.elements()[material.element].parameters.length);
      anchor.has_slope = true;
      for (int k = 0; k < 4; ++k) anchor.slope_weight[k] = shape.ds[k];
    }
  }
  return anchor;
}

// The same, its errors prefixed with the side ("journal: no rigid body named 'x'").
JointAnchor ResolveAnchor(const Model& model, const JointAnchorSpec& spec, const char* side) {
  try {
    return ResolveNamedAnchor(model, spec);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", side, error.what()));
  }
}

}  // namespace

void ModelBuilder::AddClearanceJoint(const ClearanceJointSpec& spec) {
  if (spec.name.empty()) throw InputError("a clearance joint needs a non-empty name");
  for (const ClearanceJoint& joint : model_.clearance_joints_)
    if (joint.name == spec.name)
      throw InputError(fmt::format("two clearance joints are named '{}'", spec.name));
  if (!(spec.clearance > 0.0) || !std::isfinite(spec.clearance))
    throw InputError(fmt::format("clearance must be positive and finite (got {})", spec.clearance));
  if (!(spec.journal_radius > spec.clearance) || !std::isfinite(spec.journal_radius))
    throw InputError(
        fmt::format("journal radius must be finite and larger than the clearance {} (got {})",
                    spec.clearance, spec.journal_radius));
  if (!spec.axis.allFinite() || !(spec.axis.norm() > 0.0))
    throw InputError("the joint axis must be a finite, non-zero vector");
  if (spec.journal.kind == JointAnchor::Kind::kGround &&
      spec.bearing.kind == JointAnchor::Kind::kGround)
    throw InputError("a clearance joint cannot join the ground to itself");
  ValidateNormalLaw(spec.normal);
  if (spec.friction) {
    ValidateFrictionLaw(*spec.friction);
    if (spec.friction->kind == FrictionLawKind::kLuGre)
      throw InputError(
          "clearance joints take a regularised friction law (tanh, ambrosio), not lugre");
  }
  ClearanceJoint joint{.name = spec.name,
                       .type = spec.type,
                       .journal = ResolveAnchor(model_, spec.journal, "journal"),
                       .bearing = ResolveAnchor(model_, spec.bearing, "bearing"),
                       .clearance = spec.clearance,
                       .journal_radius = spec.journal_radius,
                       .axis = spec.axis.normalized(),
                       .normal = spec.normal,
                       .friction = spec.friction};
  // The ground sits where it is put, or concentric with the other side.
  for (auto [anchor, given, other] : {std::tuple{&joint.journal, &spec.journal, &joint.bearing},
                                      std::tuple{&joint.bearing, &spec.bearing, &joint.journal}})
    if (anchor->kind == JointAnchor::Kind::kGround)
      anchor->ground_point = given->position ? *given->position : InitialCenter(model_, *other);
  model_.clearance_joints_.push_back(joint);
}

}  // namespace ancfnet
