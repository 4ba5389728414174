#include "ancfnet/model/rigid_body_kinematics.hpp"

#include <cmath>

namespace ancfnet {

Matrix3d ExpRotation(const Vector3d& psi) {
  const double theta2 = psi.squaredNorm();
  const Matrix3d k = Skew(psi);
  double a, b;  // sin θ/θ and (1 − cos θ)/θ²
  if (theta2 < 1e-8) {
    a = 1.0 - theta2 / 6.0;
    b = 0.5 - theta2 / 24.0;
  } else {
    const double theta = std::sqrt(theta2);
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta2;
  }
  return Matrix3d::Identity() + a * k + b * k * k;
}

BodyPose CalcBodyPose(const RigidBody& body, const VectorXd& q, const Matrix3d& rotation_ref) {
  return {q.segment<3>(body.position_dof()),
          rotation_ref * ExpRotation(q.segment<3>(body.rotation_dof()))};
}

BodyVelocity CalcBodyVelocity(const RigidBody& body, const VectorXd& v) {
  return {v.segment<3>(body.position_dof()), v.segment<3>(body.rotation_dof())};
}

Matrix3x6d CalcPointVelocityMap(const BodyPose& pose, const Vector3d& p_W) {
  Matrix3x6d g;
  g.leftCols<3>().setIdentity();
  g.rightCols<3>() = -Skew(p_W - pose.p_WB) * pose.R_WB;
  return g;
}

Vector6d CalcGeneralizedForce(const BodyPose& pose, const Vector3d& p_W, const Vector3d& f_W) {
  Vector6d q;
  q << f_W, pose.R_WB.transpose() * (p_W - pose.p_WB).cross(f_W);
  return q;
}

}  // namespace ancfnet
