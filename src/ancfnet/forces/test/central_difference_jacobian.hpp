#pragma once
/// @file Test helper: the Jacobian of generalised forces F(q, v) by central differences, with
/// respect to the positions q or the velocities v.

#include "ancfnet/common/types.hpp"

namespace ancfnet::test {

/// Column j: (F(x + h e_j) − F(x − h e_j)) / 2h, x = q (positions) or v.
template <class Forces>
MatrixXd CalcCentralDifferenceJacobian(const Forces& forces, const VectorXd& q, const VectorXd& v,
                                       bool positions, double h = 1e-8) {
  MatrixXd jacobian(q.size(), q.size());
  for (Index j = 0; j < q.size(); ++j) {
    VectorXd qp = q, qm = q, vp = v, vm = v;
    VectorXd& plus = positions ? qp : vp;
    VectorXd& minus = positions ? qm : vm;
    plus[j] += h;
    minus[j] -= h;
    jacobian.col(j) = (forces(qp, vp) - forces(qm, vm)) / (2 * h);
  }
  return jacobian;
}

}  // namespace ancfnet::test
