#include "ancfnet/forces/section_lock.hpp"

#include "ancfnet/common/skew.hpp"

namespace ancfnet {
namespace {

using Matrix96d = Eigen::Matrix<double, 9, 6>;

// ∂vec(R)/∂(y, z) of R = C Dᵀ (vec column by column): the rows of column b of R are
// D_b1 ∂(y × z) + D_b2 ∂y + D_b3 ∂z, with ∂(y × z)/∂y = −z̃ and ∂(y × z)/∂z = ỹ (eq. L3).
Matrix96d SectionRotationJacobian(const Vector3d& y, const Vector3d& z, const Matrix3d& frame) {
  Matrix96d jacobian;
  const Matrix3d identity = Matrix3d::Identity();
  for (int b = 0; b < 3; ++b) {
    jacobian.block<3, 3>(3 * b, 0) = -frame(b, 0) * Skew(z) + frame(b, 1) * identity;
    jacobian.block<3, 3>(3 * b, 3) = frame(b, 0) * Skew(y) + frame(b, 2) * identity;
  }
  return jacobian;
}

}  // namespace

Matrix3d CalcSectionRotation(const Vector3d& y, const Vector3d& z, const Matrix3d& frame) {
  Matrix3d c;
  c << y.cross(z), y, z;
  return c * frame.transpose();
}

SectionLockResult CalcSectionLock(double stiffness, const Matrix3d& first_frame,
                                  const Matrix3d& second_frame, const Vector12d& x,
                                  bool with_stiffness) {
  const Vector3d y1 = x.segment<3>(0), z1 = x.segment<3>(3);
  const Vector3d y2 = x.segment<3>(6), z2 = x.segment<3>(9);
  const Matrix3d error =
      CalcSectionRotation(y1, z1, first_frame) - CalcSectionRotation(y2, z2, second_frame);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> e(error.data());
  // G = ∂vec(E)/∂x = [J₁, −J₂].
  Eigen::Matrix<double, 9, 12> g;
  g.leftCols<6>() = SectionRotationJacobian(y1, z1, first_frame);
  g.rightCols<6>() = -SectionRotationJacobian(y2, z2, second_frame);
  SectionLockResult out;
  const double half_k = 0.5 * stiffness;
  out.energy = 0.5 * half_k * e.squaredNorm();
  out.gradient = half_k * g.transpose() * e;  // eq. L3
  if (!with_stiffness) return out;
  // Eq. L4: (k/2) [GᵀG + Σ_m E_m ∇²E_m]; only y × z has second derivatives, ∂²/∂y∂z of
  // Σ_m E_m (R_i)_m being −w̃_i with w_i = E d₁,ᵢ (with the sign of R_i in E).
  out.stiffness = half_k * g.transpose() * g;
  const Matrix3d w1 = Skew(error * first_frame.col(0));
  const Matrix3d w2 = Skew(error * second_frame.col(0));
  out.stiffness.block<3, 3>(0, 3) -= half_k * w1;
  out.stiffness.block<3, 3>(3, 0) += half_k * w1;
  out.stiffness.block<3, 3>(6, 9) += half_k * w2;
  out.stiffness.block<3, 3>(9, 6) -= half_k * w2;
  return out;
}

}  // namespace ancfnet
