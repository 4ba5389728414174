#include "ancfnet/model/coordinate_scales.hpp"

#include <Eigen/Geometry>

namespace ancfnet {

double CalcModelLengthScale(const Model& model) {
  if (!model.elements().empty()) {
    double total = 0.0;
    for (const CableElement& element : model.elements()) total += element.parameters.length;
    return total / static_cast<double>(model.elements().size());
  }
  Eigen::AlignedBox3d box;
  const VectorXd& q = model.initial_positions();
  for (const PointMass& mass : model.point_masses()) box.extend(q.segment<3>(mass.dof));
  for (const RigidBody& body : model.rigid_bodies()) box.extend(q.segment<3>(body.position_dof()));
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  return diagonal > 0.0 ? diagonal : 1.0;
}

VectorXd CalcCoordinateScales(const Model& model) {
  // Every coordinate is a position, a gradient or a rotation; gradients and rotations are 1.
  VectorXd scales = VectorXd::Ones(model.num_dofs());
  const double length = CalcModelLengthScale(model);
  for (const CableNode& node : model.nodes())
    scales.segment<3>(node.position_dof).setConstant(length);
  for (const PointMass& mass : model.point_masses())
    scales.segment<3>(mass.dof).setConstant(length);
  for (const RigidBody& body : model.rigid_bodies())
    scales.segment<3>(body.position_dof()).setConstant(length);
  return scales;
}

}  // namespace ancfnet
