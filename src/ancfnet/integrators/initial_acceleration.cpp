#include "ancfnet/integrators/initial_acceleration.hpp"

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {

bool CalcInitialAcceleration(const Model& model, const DofMap& dofs, const DampingModel& damping,
                             Workspace& ws, State* state) {
  CalcInternalForces(model, state->q, state->v, ws);
  damping.AddForces(state->v, ws);
  CalcExternalForces(model, state->q, 1.0, ws);
  SystemMatrix mass(model, dofs);
  AssembleMassMatrix(model, ws, &mass);
  SparseLinearSolver solver;
  if (!solver.Factorize(mass.matrix())) return false;
  VectorXd rhs, a_free;
  dofs.Restrict(ws.external_force - ws.internal_force, &rhs);
  solver.Solve(rhs, &a_free);
  state->a.setZero();
  dofs.AddExpanded(a_free, 1.0, &state->a);
  return true;
}

}  // namespace ancfnet
