#include "ancfnet/forces/section_lock_forces.hpp"

#include "ancfnet/forces/section_lock.hpp"

namespace ancfnet {
namespace {

// x = (r_y,1, r_z,1, r_y,2, r_z,2) of a lock: the six coordinates from each node's section_dof.
Vector12d GatherSections(const Model& model, const SectionLock& lock, const VectorXd& q) {
  Vector12d x;
  x.head<6>() = q.segment<6>(model.nodes()[lock.first_node].section_dof);
  x.tail<6>() = q.segment<6>(model.nodes()[lock.second_node].section_dof);
  return x;
}

SectionLockResult CalcLock(const Model& model, const SectionLock& lock, const VectorXd& q,
                           bool with_stiffness) {
  return CalcSectionLock(lock.stiffness, lock.first_frame, lock.second_frame,
                         GatherSections(model, lock, q), with_stiffness);
}

}  // namespace

void AddSectionLockForces(const Model& model, const VectorXd& q, Workspace& ws) {
  for (const SectionLock& lock : model.section_locks()) {
    const Vector12d gradient = CalcLock(model, lock, q, false).gradient;
    ws.internal_force.segment<6>(model.nodes()[lock.first_node].section_dof) += gradient.head<6>();
    ws.internal_force.segment<6>(model.nodes()[lock.second_node].section_dof) += gradient.tail<6>();
  }
}

void AddSectionLockJacobians(const Model& model, const VectorXd& q, double stiffness_weight,
                             SystemMatrix* matrix) {
  const auto& locks = model.section_locks();
  for (std::size_t l = 0; l < locks.size(); ++l)
    matrix->AddSectionLockBlock(static_cast<Index>(l), CalcLock(model, locks[l], q, true).stiffness,
                                stiffness_weight);
}

double CalcSectionLockEnergy(const Model& model, const VectorXd& q) {
  double energy = 0.0;
  for (const SectionLock& lock : model.section_locks())
    energy += CalcLock(model, lock, q, false).energy;
  return energy;
}

}  // namespace ancfnet
