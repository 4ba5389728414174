#pragma once
/// @file Assembly of the section locks (forces/section_lock.hpp) of a model: each adds ∂W/∂x to
/// Q_int on the r_y, r_z coordinates of its two beam nodes, and c_K ∂²W/∂x² to the iteration
/// matrix. Elastic: a lock dissipates nothing.

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Adds every section lock's force ∂W/∂x to ws.internal_force.
void AddSectionLockForces(const Model& model, const VectorXd& q, Workspace& ws);

/// Adds stiffness_weight · ∂²W/∂x² of every section lock to `matrix`.
void AddSectionLockJacobians(const Model& model, const VectorXd& q, double stiffness_weight,
                             SystemMatrix* matrix);

/// Energy W stored in the section locks (J).
double CalcSectionLockEnergy(const Model& model, const VectorXd& q);

}  // namespace ancfnet
