// ModelBuilder::AddClearanceJoint (model/model_builder.hpp): resolves and checks a clearance
// joint's anchors, geometry and laws.

#include <fmt/format.h>

#include <cmath>
#include <tuple>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/joint_anchor_resolution.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

void ModelBuilder::AddClearanceJoint(const ClearanceJointSpec& spec) {
  if (spec.name.empty()) throw InputError("a clearance joint needs a non-empty name");
  CheckJointNameIsFree(spec.name);
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
  if (spec.friction) ValidateFrictionLaw(*spec.friction);
  ClearanceJoint joint{.name = spec.name,
                       .type = spec.type,
                       .journal = ResolveJointAnchor(model_, spec.journal, "journal"),
                       .bearing = ResolveJointAnchor(model_, spec.bearing, "bearing"),
                       .clearance = spec.clearance,
                       .journal_radius = spec.journal_radius,
                       .axis = spec.axis.normalized(),
                       .normal = spec.normal,
                       .friction = spec.friction};
  // The ground sits where it is put, or concentric with the other side.
  for (auto [anchor, given, other] : {std::tuple{&joint.journal, &spec.journal, &joint.bearing},
                                      std::tuple{&joint.bearing, &spec.bearing, &joint.journal}})
    if (anchor->kind == JointAnchor::Kind::kGround)
      anchor->ground_point = given->position ? *given->position : CalcInitialAnchorCenter(model_, *other);
  model_.clearance_joints_.push_back(joint);
}

}  // namespace ancfnet
