#pragma once
/// @file A scalar regularised friction law (friction_law.hpp) applied to a slip velocity vector in
/// the tangent plane of a contact: f_t = F(|v_t|) v̂_t, F ≤ 0 the law's force at the slip speed,
/// with the 3×3 Jacobian an implicit integrator needs (docs/theory.md, "Contact force laws").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/friction_law.hpp"

namespace ancfnet {

/// A tangential friction force and its derivatives.
struct TangentialFriction {
  Vector3d force = Vector3d::Zero();             ///< f_t (N), opposing v_t
  Matrix3d dforce_dvelocity = Matrix3d::Zero();  ///< ∂f_t/∂v_t (N s/m)
  Vector3d dforce_dnormal = Vector3d::Zero();    ///< ∂f_t/∂N (–)
};

/// f_t = F(s) v̂ with s = |v_t|, v̂ = v_t/s, and
///   ∂f_t/∂v_t = F'(s) v̂ v̂ᵀ + (F(s)/s) (I − v̂ v̂ᵀ),
/// which tends to F'(0) I as s → 0 (a regularised law has F(0) = 0 and a finite slope there): below
/// a slip speed of 10⁻¹² of the law's regularisation speed the isotropic limit is used. `v_t` must
/// already lie in the tangent plane. For kAmbrosio and kTanh (the regularised laws); throws
/// std::logic_error for kLuGre, whose bristle state is per direction.
TangentialFriction CalcTangentialFriction(const FrictionLaw& law, const Vector3d& v_t,
                                          double normal_force);

}  // namespace ancfnet
