#include "ancfnet/forces/joint_anchor.hpp"

#include "ancfnet/forces/slope_moment.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

Matrix3d AnchorMotion::GeometricStiffness(int k, int l, const Vector3d& f,
                                          const Vector3d& m) const {
  if (kind == JointAnchor::Kind::kBody) {
    if (k != 1 || l != 1) return Matrix3d::Zero();
    return Skew(body_point) * Skew(rotation.transpose() * f) + Skew(rotation.transpose() * m);
  }
  if (kind == JointAnchor::Kind::kPoint && has_slope)
    return slope_weight[k] * slope_weight[l] * CalcSlopeMomentJacobian(m, slope);
  return Matrix3d::Zero();
}

Vector3d CalcAnchorCenter(const Model& model, const JointAnchor& anchor, const VectorXd& q,
                          const std::vector<Matrix3d>& rotation) {
  switch (anchor.kind) {
    case JointAnchor::Kind::kGround:
      return anchor.ground_point;
    case JointAnchor::Kind::kBody:
      return CalcBodyPose(model.rigid_bodies()[anchor.body], q, rotation[anchor.body])
          .PointInWorld(anchor.body_point);
    case JointAnchor::Kind::kPoint:
      break;
  }
  Vector3d c = Vector3d::Zero();
  for (int k = 0; k < anchor.num_blocks; ++k) c += anchor.weight[k] * q.segment<3>(anchor.dof[k]);
  return c;
}

AnchorMotion CalcAnchorMotion(const Model& model, const JointAnchor& anchor, const VectorXd& q,
                              const VectorXd& v, const std::vector<Matrix3d>& rotation) {
  AnchorMotion out;
  out.kind = anchor.kind;
  switch (anchor.kind) {
    case JointAnchor::Kind::kGround:
      out.center = CalcAnchorCenter(model, anchor, q, rotation);
      return out;
    case JointAnchor::Kind::kBody: {
      const RigidBody& body = model.rigid_bodies()[anchor.body];
      const BodyPose pose = CalcBodyPose(body, q, rotation[anchor.body]);
      const BodyVelocity velocity = CalcBodyVelocity(body, v);
      const Matrix3d& R = pose.R_WB;
      const Vector3d& s = anchor.body_point;
      out.num_blocks = 2;
      out.dof = {body.position_dof(), body.rotation_dof()};
      out.rotation = R;
      out.body_point = s;
      out.center = CalcAnchorCenter(model, anchor, q, rotation);
      out.velocity = velocity.v_WB + R * velocity.w_B.cross(s);
      out.angular_velocity = R * velocity.w_B;
      out.a = {Matrix3d::Identity(), -R * Skew(s)};
      out.b = {Matrix3d::Zero(), R};
      // δR = R δψ̃: δ(R (ω × s)) = −R (ω × s)~ δψ, δ(R ω) = −R ω̃ δψ.
      out.c = {Matrix3d::Zero(), -R * Skew(velocity.w_B.cross(s))};
      out.d = {Matrix3d::Zero(), -R * Skew(velocity.w_B)};
      return out;
    }
    case JointAnchor::Kind::kPoint:
      break;
  }
  out.num_blocks = anchor.num_blocks;
  out.dof = anchor.dof;
  out.has_slope = anchor.has_slope;
  out.slope_weight = anchor.slope_weight;
  out.center = CalcAnchorCenter(model, anchor, q, rotation);
  Vector3d& slope_rate = out.slope_rate;
  for (int k = 0; k < anchor.num_blocks; ++k) {
    out.velocity += anchor.weight[k] * v.segment<3>(anchor.dof[k]);
    out.slope += anchor.slope_weight[k] * q.segment<3>(anchor.dof[k]);
    slope_rate += anchor.slope_weight[k] * v.segment<3>(anchor.dof[k]);
    out.a[k] = anchor.weight[k] * Matrix3d::Identity();
    out.b[k].setZero();
    out.c[k].setZero();
    out.d[k].setZero();
  }
  if (!anchor.has_slope) return out;
  // ω = a × ȧ/g, g = |a|²: ∂ω/∂ȧ = ã/g, ∂ω/∂a = −(ȧ)~/g − 2 (a × ȧ) aᵀ/g².
  const Vector3d& a = out.slope;
  const double g = a.squaredNorm();
  out.angular_velocity = a.cross(slope_rate) / g;
  const Matrix3d domega_da =
      -Skew(slope_rate) / g - 2.0 / (g * g) * a.cross(slope_rate) * a.transpose();
  for (int k = 0; k < anchor.num_blocks; ++k) {
    out.b[k] = anchor.slope_weight[k] / g * Skew(a);
    out.d[k] = anchor.slope_weight[k] * domega_da;
  }
  return out;
}

}  // namespace ancfnet
