#include "ancfnet/contact/self_pair_jacobian.hpp"

namespace ancfnet {
namespace {

using Matrix3x24d = Eigen::Matrix<double, 3, 24>;
using RowVector24d = Eigen::Matrix<double, 1, 24>;

// The side's point displacement ±W δe at fixed parameter, and δΔ = D δe, in its columns.
void FillSide(const SelfPairSide& side, int first_column, double sign, Matrix3x24d* point,
              Matrix3x24d* axis) {
  for (int k = 0; k < side.num_blocks; ++k) {
    point->middleCols<3>(first_column + 3 * k) = sign * side.weights[k] * Matrix3d::Identity();
    axis->middleCols<3>(first_column + 3 * k) = side.weight_rates[k] * Matrix3d::Identity();
  }
}

// Rows of Q from δf and the parameter's variation: a: −w_k δf − d_k f δp; b: the opposite.
void AddRows(const SelfPairSide& side, int first_row, double sign, const Matrix3x24d& df,
             const Vector3d& f, const RowVector24d& dp, double scale, Matrix24d* jacobian) {
  for (int k = 0; k < side.num_blocks; ++k)
    jacobian->middleRows<3>(first_row + 3 * k) +=
        sign * scale * (side.weights[k] * df + side.weight_rates[k] * f * dp);
}

}  // namespace

Matrix24d CalcSelfPairJacobian(const SelfPairSide& a, const SelfPairSide& b,
                               const Vector3d& separation, const ContactPairForce& force,
                               double stiffness_weight, double damping_weight) {
  Matrix24d jacobian = Matrix24d::Zero();
  Matrix3x24d point = Matrix3x24d::Zero(), axis_a = Matrix3x24d::Zero(),
              axis_b = Matrix3x24d::Zero();
  FillSide(a, 0, 1.0, &point, &axis_a);
  FillSide(b, 12, -1.0, &point, &axis_b);
  const Vector3d& f = force.force;

  if (stiffness_weight != 0.0) {
    // The closest-point parameters: residuals of Δ_aᵀ x = 0 and Δ_bᵀ x = 0 at fixed (s*, t*).
    const RowVector24d ra = separation.transpose() * axis_a + a.axis.transpose() * point;
    const RowVector24d rb = separation.transpose() * axis_b + b.axis.transpose() * point;
    RowVector24d ds = RowVector24d::Zero(), dt = RowVector24d::Zero();
    const double aa = a.axis.squaredNorm(), ab = a.axis.dot(b.axis), bb = b.axis.squaredNorm();
    if (a.moving_point && b.moving_point) {
      // [aa −ab; ab −bb] (δs, δt) = −(ra, rb).
      const double det = ab * ab - aa * bb;
      ds = -(-bb * ra + ab * rb) / det;
      dt = -(-ab * ra + aa * rb) / det;
    } else if (a.moving_point) {
      ds = -ra / aa;
    } else if (b.moving_point) {
      dt = rb / bb;
    }
    const Matrix3x24d dx = point + a.axis * ds - b.axis * dt;
    const Matrix3x24d df =
        force.dforce_dx * dx + force.dforce_dv * (a.axis_rate * ds - b.axis_rate * dt);
    AddRows(a, 0, -1.0, df, f, ds, stiffness_weight, &jacobian);
    AddRows(b, 12, 1.0, df, f, dt, stiffness_weight, &jacobian);
  }

  if (damping_weight != 0.0) {
    const Matrix3x24d df = force.dforce_dv * point;
    AddRows(a, 0, -1.0, df, f, RowVector24d::Zero(), damping_weight, &jacobian);
    AddRows(b, 12, 1.0, df, f, RowVector24d::Zero(), damping_weight, &jacobian);
  }
  return jacobian;
}

}  // namespace ancfnet
