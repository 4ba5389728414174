#include "ancfnet/integrators/initial_acceleration.hpp"

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {

bool CalcInitialAcceleration(const Model& model, const DofMap& dofs, SystemForces& forces,
                             Workspace& ws, State* state) {
  forces.FindContacts(*state, 0.0, /*with_step_size=*/false);
  forces.Calc(state->q, state->v, state->contact_history, 1.0, ws);
  SystemMatrix mass(model, dofs);
  AssembleMassMatrix(model, ws, &mass);
  SparseLinearSolver solver;
  VectorXd rhs, solution;
  dofs.Restrict(ws.external_force - ws.internal_force, &rhs);
  JointConstraints constraints(model);
  if (constraints.empty()) {
    if (!solver.Factorize(mass.matrix())) return false;
    solver.Solve(rhs, &solution);
    state->a.setZero();
    dofs.AddExpanded(solution, 1.0, &state->a);
    return true;
  }
  // With ideal joints both solves use [M Gᵀ; G 0] (Géradin & Cardona 2001):
  // first the velocities are projected onto G v = 0 in the metric of M,
  //   [M Gᵀ; G 0] (Δv, μ) = (0, −G v),
  // then the acceleration and multipliers solve M a + Gᵀλ = Q_ext − Q_int, G a = −Ġv
  // (the accelerations of the fixed coordinates taken as zero).
  const Index n = dofs.num_unknowns();
  const Index m = constraints.size();
  constraints.Evaluate(state->q, state->v, ws.body_rotation);
  SparseMatrixd bordered;
  constraints.AssembleBorderedMatrix(mass.matrix(), dofs, &bordered);
  if (!solver.Factorize(bordered)) return false;
  VectorXd velocity_rhs(n + m);
  velocity_rhs << VectorXd::Zero(n), -constraints.CalcRate(state->v);
  solver.Solve(velocity_rhs, &solution);
  dofs.AddExpanded(solution, 1.0, &state->v);
  forces.Calc(state->q, state->v, state->contact_history, 1.0, ws);
  dofs.Restrict(ws.external_force - ws.internal_force, &rhs);
  constraints.Evaluate(state->q, state->v, ws.body_rotation);
  VectorXd acceleration_rhs(n + m);
  acceleration_rhs << rhs, -constraints.convective_term();
  solver.Solve(acceleration_rhs, &solution);
  state->a.setZero();
  dofs.AddExpanded(solution, 1.0, &state->a);
  state->multipliers = solution.tail(m);
  return true;
}

}  // namespace ancfnet
