#pragma once
/// @file The gyroscopic term of Euler's equations J_B ω̇ + ω × J_B ω = M_B (body frame): an
/// internal force of the rotation coordinates (on the left-hand side, like Q_int), with Jacobian
///   ∂(ω × J ω)/∂ω = ω̃ J − (J ω)~,
/// which is not symmetric (Géradin & Cardona 2001, "Flexible multibody dynamics", §5.4).

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// ω × J ω (N m).
Vector3d CalcGyroscopicForce(const Matrix3d& inertia, const Vector3d& w_B);
/// ω̃ J − (J ω)~ (N m s).
Matrix3d CalcGyroscopicJacobian(const Matrix3d& inertia, const Vector3d& w_B);

}  // namespace ancfnet
