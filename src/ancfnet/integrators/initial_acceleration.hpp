#pragma once
/// @file The consistent initial acceleration of an implicit scheme.

#include "ancfnet/assembly/dof_map.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/solvers/system_forces.hpp"
#include "ancfnet/state/state.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Sets state->a to a₀ = M⁻¹ (Q_ext − Q_int)(q₀, v₀) on the free coordinates of `dofs` (0 on the
/// fixed ones), the forces those of `forces` (damping and the contacts touching at the state
/// included; SystemForces::FindContacts at the state), left in `ws`. Returns false
/// when the mass matrix is singular. With ideal joints (forces/joint_constraints.hpp) it first
/// projects the free velocities onto G v = 0 in the metric of M, then solves the bordered
/// system for a₀ and the multipliers λ₀ (state->multipliers), with G a₀ = −Ġv.
bool CalcInitialAcceleration(const Model& model, const DofMap& dofs, SystemForces& forces,
                             Workspace& ws, State* state);

}  // namespace ancfnet
