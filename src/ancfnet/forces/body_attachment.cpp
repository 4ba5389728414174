#include "ancfnet/forces/body_attachment.hpp"

namespace ancfnet {

BodyAttachmentResult CalcBodyAttachment(const BodyAttachmentInput& in, bool jacobians) {
  const Matrix3d& R = in.pose.R_WB;
  const Vector3d& w = in.velocity.w_B;
  const Vector3d w_cross_s = w.cross(in.s_B);
  const Vector3d d = in.p - in.pose.PointInWorld(in.s_B);
  const Vector3d u = in.p_dot - (in.velocity.v_WB + R * w_cross_s);
  const double k = in.stiffness;
  const double c = in.damping;

  BodyAttachmentResult out;
  out.viscous_force = -c * u;
  out.force_on_point = -k * d + out.viscous_force;
  out.energy = 0.5 * k * d.squaredNorm();
  const Matrix3d s_skew = Skew(in.s_B);
  const auto generalized = [&](const Vector3d& f) {
    Vector9d q;
    q << -f, f, s_skew * (R.transpose() * f);
    return q;
  };
  out.generalized = generalized(out.force_on_point);
  out.generalized_viscous = generalized(out.viscous_force);
  if (!jacobians) return out;

  // ∂f/∂(p, x, ψ) and ∂f/∂(ṗ, ẋ, ω), 3 × 9 each.
  Eigen::Matrix<double, 3, 9> df_dq, df_dv;
  const Matrix3d identity = Matrix3d::Identity();
  df_dq << -k * identity, k * identity, -k * R * s_skew - c * R * Skew(w_cross_s);
  df_dv << -c * identity, c * identity, -c * R * s_skew;
  const Matrix3d moment_map = s_skew * R.transpose();
  for (auto [jacobian, df] : {std::pair{&out.stiffness, &df_dq}, {&out.damping, &df_dv}}) {
    jacobian->middleRows<3>(0) = -*df;
    jacobian->middleRows<3>(3) = *df;
    jacobian->middleRows<3>(6) = moment_map * *df;
  }
  out.stiffness.block<3, 3>(6, 6) += s_skew * Skew(R.transpose() * out.force_on_point);
  return out;
}

}  // namespace ancfnet
