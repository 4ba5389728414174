#pragma once
/// @file The rotational spring that holds the cross-sections of two beam nodes together (a knot
/// of beam threads, docs/theory.md, "Section lock at a knot"). Pure function on fixed-size types,
/// no allocation.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Energy, gradient and Hessian of a section lock.
struct SectionLockResult {
  double energy = 0.0;                      ///< W (J)
  Vector12d gradient = Vector12d::Zero();   ///< ∂W/∂x: the internal force on x (N m)
  Matrix12d stiffness = Matrix12d::Zero();  ///< ∂²W/∂x², symmetric
};

/// The rotation R = C Dᵀ that a beam node's section has turned through from its reference
/// frame D = [d₁ d₂ d₃] (orthonormal, d₁ = d₂ × d₃), estimated from its section gradients y = r_y,
/// z = r_z as C = [y × z, y, z] (eq. L1). Exactly the rotation when y, z are orthonormal; the
/// axial stretch and shear of the thread (in r_x) do not enter.
Matrix3d CalcSectionRotation(const Vector3d& y, const Vector3d& z, const Matrix3d& frame);

/// With x = (r_y,1, r_z,1, r_y,2, r_z,2), the section gradients of the two nodes:
/// W = (k/4) |R₁ − R₂|²_F (eq. L2), the rotations of CalcSectionRotation, and its derivatives
/// (eq. L3, L4; the Hessian only when `with_stiffness`). For a relative rotation θ of rigid
/// sections W = k (1 − cos θ): the torque k sin θ ≈ k θ, so k (N m/rad) is the lock's rotational
/// stiffness, about every axis alike. Invariant under a rotation of both sections together.
SectionLockResult CalcSectionLock(double stiffness, const Matrix3d& first_frame,
                                  const Matrix3d& second_frame, const Vector12d& x,
                                  bool with_stiffness);

}  // namespace ancfnet
