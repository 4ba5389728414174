#pragma once
/// @file The bristle (LuGre) friction law in the tangent plane of a contact: a deflection vector
/// z carried by the contact pair, advanced over a time step by implicit Euler with the
/// end-of-step slip velocity, and the friction force at the end of the step with its exact
/// derivative with respect to that velocity (docs/theory.md, "The LuGre law in contact").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/friction_law.hpp"
#include "ancfnet/contact/laws/tangential_friction.hpp"

namespace ancfnet {

/// The deflection at the end of a step and the friction force there.
struct TangentialBristleStep {
  Vector3d deflection = Vector3d::Zero();  ///< z₁ (m), in the tangent plane
  /// f_t (N) with ∂f_t/∂v_t (N s/m, ∂z₁/∂v_t included) and ∂f_t/∂N (–).
  TangentialFriction friction;
  /// ∂f_t/∂z₀ = c I with c = −N (σ₀ − σ₁ φ)/(1 + h φ) (N/m): c (–).
  double dforce_ddeflection = 0.0;
};

/// The isotropic 2-D bristle of Velenis, Tsiotras, Canudas de Wit & Sorine (2005), "Dynamic tyre
/// friction models for combined longitudinal and lateral vehicle motion", with an isotropic bristle
/// stiffness σ₀ I and bristle forces proportional to N:
///   ż = v − φ(s) z,  φ(s) = σ₀ s/g(s),  s = |v|,
///   f_t = −N (σ₀ z + σ₁ ż) − σ₂ v,
/// g the law's Stribeck curve. One implicit-Euler step of size h ≥ 0 from z₀ with the
/// end-of-step slip velocity v,
///   ż = (v − φ z₀)/(1 + h φ),  z₁ = z₀ + h ż,
/// is unconditionally stable for the stiff bristle; h = 0 gives the law's own rate at z₀ (the
/// force at a state, for outputs). Its derivative,
///   ∂ż/∂v = (I − φ'(s) z₁ v̂ᵀ)/(1 + h φ),  ∂f_t/∂v = −N (h σ₀ + σ₁) ∂ż/∂v − σ₂ I,
/// takes ∂s/∂v = 0 at v = 0; with respect to the deflection the step starts from,
///   ∂z₁/∂z₀ = I/(1 + h φ),  ∂ż/∂z₀ = −φ I/(1 + h φ),  ∂f_t/∂z₀ = −N (σ₀ − σ₁ φ)/(1 + h φ) I. z₀
///   and v must lie in the tangent plane (then z₁ does too); N ≤ 0
/// leaves only the viscous term. Throws std::logic_error unless `law` is kLuGre and h ≥ 0.
TangentialBristleStep CalcTangentialBristleFriction(const FrictionLaw& law,
                                                    const Vector3d& deflection, const Vector3d& v_t,
                                                    double normal_force, double step);

}  // namespace ancfnet
