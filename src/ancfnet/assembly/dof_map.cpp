#include "ancfnet/assembly/dof_map.hpp"

#include "ancfnet/model/model.hpp"

namespace ancfnet {

DofMap::DofMap(const Model& model, bool eliminate_fixed)
    : coordinate_to_unknown_(model.num_dofs(), -1) {
  for (const PrescribedBlock& block : model.prescribed())
    for (int k = 0; k < 3; ++k) prescribed_dofs_.push_back(block.dof + k);
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (eliminate_fixed && model.fixed()[i]) continue;
    coordinate_to_unknown_[i] = static_cast<Index>(free_dofs_.size());
    free_dofs_.push_back(i);
  }
}

DofMap DofMap::FreeCoordinates(const Model& model) { return DofMap(model, true); }

DofMap DofMap::AllCoordinates(const Model& model) { return DofMap(model, false); }

void DofMap::Restrict(const VectorXd& full, VectorXd* unknowns) const {
  unknowns->resize(num_unknowns());
  for (Index i = 0; i < num_unknowns(); ++i) (*unknowns)[i] = full[free_dofs_[i]];
}

void DofMap::AddExpanded(const VectorXd& unknowns, double scale, VectorXd* full) const {
  for (Index i = 0; i < num_unknowns(); ++i) (*full)[free_dofs_[i]] += scale * unknowns[i];
}

}  // namespace ancfnet
