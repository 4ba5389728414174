// The attachment's and the gyroscopic term's Jacobians against central finite differences, the
// rotation perturbed as R_ref exp(ψ̃) about ψ = 0, where the tangent operator is exactly I.

#include "ancfnet/forces/body_attachment.hpp"

#include <gtest/gtest.h>

#include "ancfnet/forces/gyroscopic_force.hpp"
#include "ancfnet/model/fixed_attachment_stiffness.hpp"

namespace ancfnet {
namespace {

// Generalised forces of an attachment at coordinates z = (p, x, ψ) and rates z_dot = (ṗ, ẋ, ω).
Vector9d Forces(const Vector9d& z, const Vector9d& z_dot, const Matrix3d& rotation_ref,
                BodyAttachmentResult* full = nullptr) {
  const BodyAttachmentResult r =
      CalcBodyAttachment({.p = z.segment<3>(0),
                          .p_dot = z_dot.segment<3>(0),
                          .pose = {z.segment<3>(3), rotation_ref * ExpRotation(z.segment<3>(6))},
                          .velocity = {z_dot.segment<3>(3), z_dot.segment<3>(6)},
                          .s_B = Vector3d(0.3, -0.2, 0.5),
                          .stiffness = 250.0,
                          .damping = 7.0});
  if (full) *full = r;
  return r.generalized;
}

TEST(BodyAttachment, JacobiansMatchFiniteDifferences) {
  const Matrix3d rotation_ref =
      Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  Vector9d z, z_dot;
  z << 0.9, 0.1, -0.3, 0.2, -0.1, 0.05, 0.0, 0.0, 0.0;
  z_dot << 0.3, -0.4, 0.8, -0.2, 0.1, 0.6, 1.5, -0.7, 2.0;
  BodyAttachmentResult r;
  Forces(z, z_dot, rotation_ref, &r);
  const double eps = 1e-6;
  for (int j = 0; j < 9; ++j) {
    Vector9d dz = Vector9d::Zero();
    dz[j] = eps;
    const Vector9d k_fd =
        (Forces(z + dz, z_dot, rotation_ref) - Forces(z - dz, z_dot, rotation_ref)) / (2.0 * eps);
    const Vector9d c_fd =
        (Forces(z, z_dot + dz, rotation_ref) - Forces(z, z_dot - dz, rotation_ref)) / (2.0 * eps);
    EXPECT_LT((k_fd - r.stiffness.col(j)).norm(), 1e-6 * r.stiffness.norm()) << "column " << j;
    EXPECT_LT((c_fd - r.damping.col(j)).norm(), 1e-6 * r.damping.norm()) << "column " << j;
  }
}

TEST(BodyAttachment, ForcesBalanceAndEnergyIsHalfKDSquared) {
  const Matrix3d rotation = Eigen::AngleAxisd(1.1, Vector3d::UnitY()).toRotationMatrix();
  Vector9d z, z_dot;
  z << 1.0, 2.0, 3.0, 0.5, 0.0, -0.5, 0.0, 0.0, 0.0;
  z_dot.setZero();
  BodyAttachmentResult r;
  const Vector9d q = Forces(z, z_dot, rotation, &r);
  // Equal and opposite: Q_p + Q_x = 0; and the moment about the body's centre is y − x × (−f).
  EXPECT_LT((q.segment<3>(0) + q.segment<3>(3)).norm(), 1e-14);
  const Vector3d s(0.3, -0.2, 0.5);
  const Vector3d d = z.segment<3>(0) - (z.segment<3>(3) + rotation * s);
  EXPECT_NEAR(r.energy, 0.5 * 250.0 * d.squaredNorm(), 1e-12);
  EXPECT_LT((r.force_on_point + 250.0 * d).norm(), 1e-12);
  EXPECT_LT(
      (q.segment<3>(6) - rotation.transpose() * (rotation * s).cross(r.force_on_point)).norm(),
      1e-12);
}

TEST(BodyAttachment, FixedStiffnessIsReducedMassTimesTenOverStepSquared) {
  EXPECT_DOUBLE_EQ(CalcFixedAttachmentStiffness(2.0, 1e-3), 2.0e8);
}

TEST(GyroscopicForce, JacobianMatchesFiniteDifferences) {
  Matrix3d j;
  j << 2.0, 0.1, -0.2, 0.1, 3.0, 0.3, -0.2, 0.3, 4.5;
  const Vector3d w(0.7, -1.2, 2.5);
  const Matrix3d jacobian = CalcGyroscopicJacobian(j, w);
  const double eps = 1e-6;
  for (int k = 0; k < 3; ++k) {
    const Vector3d dw = eps * Vector3d::Unit(k);
    const Vector3d fd =
        (CalcGyroscopicForce(j, w + dw) - CalcGyroscopicForce(j, w - dw)) / (2.0 * eps);
    EXPECT_LT((fd - jacobian.col(k)).norm(), 1e-8) << "column " << k;
  }
  // The term does no work: ω · (ω × J ω) = 0.
  EXPECT_NEAR(w.dot(CalcGyroscopicForce(j, w)), 0.0, 1e-13);
}

}  // namespace
}  // namespace ancfnet
