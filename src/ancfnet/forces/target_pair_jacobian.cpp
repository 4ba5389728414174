#include "ancfnet/forces/target_pair_jacobian.hpp"

namespace ancfnet {
namespace {

using Matrix3x18d = Eigen::Matrix<double, 3, 18>;
using RowVector18d = Eigen::Matrix<double, 1, 18>;

// Rows of Q from the variation δf of the force (3 × 18 columns), of t* and of the body's moment
// arm a: probe −w_k δf − d_k f δt*, body δf and Rᵀ (a × δf − f × δa).
void AddRows(const TargetPairGeometry& g, const Vector3d& f, const Matrix3x18d& df,
             const RowVector18d& dt, const Matrix3x18d& da, const Vector3d& arm, double scale,
             Matrix18d* jacobian) {
  for (int k = 0; k < g.num_blocks; ++k)
    jacobian->middleRows<3>(3 * k) -= scale * (g.weights[k] * df + g.weight_rates[k] * f * dt);
  if (!g.on_body) return;
  jacobian->middleRows<3>(12) += scale * df;
  jacobian->middleRows<3>(15) += scale * g.pose.R_WB.transpose() * (Skew(arm) * df - Skew(f) * da);
}

}  // namespace

Matrix18d CalcTargetPairJacobian(const TargetPairGeometry& g, const ContactPairForce& force,
                                 double stiffness_weight, double damping_weight) {
  Matrix18d jacobian = Matrix18d::Zero();
  const Matrix3d identity = Matrix3d::Identity();
  const Vector3d& n = g.normal;
  const Vector3d& f = force.force;
  const Matrix3d& dforce_dv = force.dforce_dv;
  // The probe point's displacement W δe at fixed t*, and δΔ = D δe.
  Matrix3x18d probe = Matrix3x18d::Zero(), axis = Matrix3x18d::Zero();
  for (int k = 0; k < g.num_blocks; ++k) {
    probe.middleCols<3>(3 * k) = g.weights[k] * identity;
    axis.middleCols<3>(3 * k) = g.weight_rates[k] * identity;
  }
  // Body: d = x − x_WB, a = s − x_WB, θ = R δψ.
  Vector3d arm = Vector3d::Zero();
  Matrix3d slip_of_position = Matrix3d::Zero();     // ∂u/∂x_rel = −ω̃ (P − φ H)
  Matrix3d surface_of_position = Matrix3d::Zero();  // ∂a/∂x_rel = P − φ H
  if (g.on_body) {
    const Vector3d d = g.point - g.pose.p_WB;
    arm = d - g.distance * n;
    surface_of_position = identity - n * n.transpose() - g.distance * g.hessian;
    slip_of_position = -Skew(g.angular_velocity) * surface_of_position;
  }

  if (stiffness_weight != 0.0) {
    // δx_rel at fixed t*, and θ.
    Matrix3x18d relative = probe, theta = Matrix3x18d::Zero();
    if (g.on_body) {
      relative.middleCols<3>(12) = -identity;
      relative.middleCols<3>(15) = Skew(g.point - g.pose.p_WB) * g.pose.R_WB;
      theta.middleCols<3>(15) = g.pose.R_WB;
    }
    RowVector18d dt = RowVector18d::Zero();
    if (g.moving_point) {
      const double curvature = g.axis.dot(g.hessian * g.axis);
      dt = -(g.axis.transpose() * g.hessian * relative + n.transpose() * axis -
             g.axis.transpose() * Skew(n) * theta) /
           curvature;
      relative += g.axis * dt;
    }
    Matrix3x18d df =
        (force.dforce_dx + dforce_dv * slip_of_position) * relative + dforce_dv * g.axis_rate * dt;
    Matrix3x18d da = Matrix3x18d::Zero();
    if (g.on_body) {
      df += (dforce_dv * Skew(g.angular_velocity.cross(arm)) - force.dforce_dnormal * Skew(n) -
             force.dforce_dbristle * Skew(g.bristle)) *
            theta;
      da = surface_of_position * relative - Skew(arm) * theta;
    }
    AddRows(g, f, df, dt, da, arm, stiffness_weight, &jacobian);
    // The moment Rᵀ (a × f) turns with the body: δ(Rᵀ) m = m̃_B δψ.
    if (g.on_body)
      jacobian.block<3, 3>(15, 15) +=
          stiffness_weight * Skew(g.pose.R_WB.transpose() * arm.cross(f));
  }

  if (damping_weight != 0.0) {
    // δu = W δė − δẋ_WB + a × R δω_B.
    Matrix3x18d slip = probe;
    if (g.on_body) {
      slip.middleCols<3>(12) = -identity;
      slip.middleCols<3>(15) = Skew(arm) * g.pose.R_WB;
    }
    AddRows(g, f, dforce_dv * slip, RowVector18d::Zero(), Matrix3x18d::Zero(), arm, damping_weight,
            &jacobian);
  }
  return jacobian;
}

}  // namespace ancfnet
