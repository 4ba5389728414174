// ModelBuilder (model/model_builder.hpp): supports of cable nodes (fixed coordinates, clamps,
// pins, a rotating clamp driven by a hub) and loads on cables (point forces, point moments,
// distributed loads).

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

Index ModelBuilder::LocateNode(const CablePointRef& at) const {
  return model_.LocateCableNode(model_.FindCable(at.cable), at.s);
}

void ModelBuilder::FixCoordinates(const CablePointRef& at, const CoordinateMask& mask) {
  const CableNode& node = model_.nodes_[LocateNode(at)];
  for (int k = 0; k < 3; ++k) {
    if (mask[k]) model_.fixed_[node.position_dof + k] = true;
    if (mask[3 + k]) model_.fixed_[node.slope_dof + k] = true;
  }
}

std::vector<Index> ModelBuilder::ClampedBlocks(Index node_index) const {
  const CableNode& node = model_.nodes_[node_index];
  if (node.section_dof < 0) return {node.position_dof, node.slope_dof};
  std::vector<Index> blocks = {node.position_dof, node.section_dof, node.section_dof + 3};
  const bool cable_uses_slope =
      std::any_of(model_.elements_.begin(), model_.elements_.end(), [&](const CableElement& e) {
        return e.beam < 0 && (e.dofs[3] == node.slope_dof || e.dofs[9] == node.slope_dof);
      });
  if (cable_uses_slope) blocks.push_back(node.slope_dof);
  return blocks;
}

void ModelBuilder::AddClamp(const CablePointRef& at) {
  for (const Index block : ClampedBlocks(LocateNode(at)))
    for (int k = 0; k < 3; ++k) model_.fixed_[block + k] = true;
}

void ModelBuilder::AddPin(const CablePointRef& at) {
  FixCoordinates(at, {true, true, true, false, false, false});
}

void ModelBuilder::AddRotatingClamp(const CablePointRef& at, const Vector3d& axis,
                                    const Vector3d& center, const AngleProfile& angle) {
  RequireFinite(axis, "hub axis");
  RequireFinite(center, "hub centre");
  if (!(axis.norm() > 0.0)) throw InputError("a hub's axis must be a non-zero vector");
  if (!std::isfinite(angle.rate)) throw InputError("a hub's rate must be finite");
  if (angle.kind == AngleProfile::Kind::kSpinUp) RequirePositive(angle.ramp_time, "spin-up time");
  AddClamp(at);
  const Index position_dof = model_.nodes_[LocateNode(at)].position_dof;
  for (const Index dof : ClampedBlocks(LocateNode(at))) {
    PrescribedBlock block;
    block.kind = PrescribedBlock::Kind::kRotation;
    block.dof = dof;
    block.initial = model_.initial_positions_.segment<3>(dof);
    block.axis = axis.normalized();
    block.center = center;
    block.is_direction = dof != position_dof;
    block.angle = angle;
    model_.prescribed_.push_back(block);
  }
}

void ModelBuilder::AddPointForce(const CablePointRef& at, const Vector3d& force) {
  RequireFinite(force, "force");
  const MaterialPoint point = model_.LocateCablePoint(model_.FindCable(at.cable), at.s);
  model_.point_forces_.push_back({point, force});
}

void ModelBuilder::AddPointMoment(const CablePointRef& at, const Vector3d& moment) {
  RequireFinite(moment, "moment");
  model_.point_moments_.push_back({LocateNode(at), moment});
}

void ModelBuilder::AddDistributedLoad(const std::string& cable, const Vector3d& force_per_length) {
  RequireFinite(force_per_length, "force per length");
  model_.distributed_loads_.push_back({model_.FindCable(cable), force_per_length});
}

}  // namespace ancfnet
