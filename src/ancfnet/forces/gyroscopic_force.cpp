#include "ancfnet/forces/gyroscopic_force.hpp"

#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {

Vector3d CalcGyroscopicForce(const Matrix3d& inertia, const Vector3d& w_B) {
  return w_B.cross(inertia * w_B);
}

Matrix3d CalcGyroscopicJacobian(const Matrix3d& inertia, const Vector3d& w_B) {
  return Skew(w_B) * inertia - Skew(inertia * w_B);
}

}  // namespace ancfnet
