#include "ancfnet/model/joint_anchor_resolution.hpp"

#include <fmt/format.h>

#include "ancfnet/common/error.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {
namespace {

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

}  // namespace

Vector3d CalcInitialAnchorCenter(const Model& model, const JointAnchor& anchor) {
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

JointAnchor ResolveJointAnchor(const Model& model, const JointAnchorSpec& spec, const char* side) {
  try {
    return ResolveNamedAnchor(model, spec);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", side, error.what()));
  }
}

}  // namespace ancfnet
