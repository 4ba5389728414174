#pragma once
/// @file The 3D point-to-point spring-damper between points P1 and P2 (cable points, knots, point
/// masses), driven by a ConnectionLaw. Pure function on fixed-size types, no allocation. The
/// derivation is in docs/theory-connections.md.

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/connection_law.hpp"

namespace ancfnet {

/// Force of a spring-damper on P2 and its Jacobians. P1 receives −force_on_2, and the Jacobians
/// with respect to r1, v1 are the negatives of those with respect to r2, v2 (d = r2 − r1):
///   ∂f2/∂r2 = stiffness, ∂f2/∂r1 = −stiffness, ∂f1/∂r1 = stiffness, ∂f1/∂r2 = −stiffness.
/// Sign: these are Jacobians of the applied force, so a stable spring has a negative
/// semi-definite `stiffness`; the tangent of the internal force Q = −f that assembly adds to K is
/// its negative.
struct SpringDamperResult {
  Vector3d force_on_2 = Vector3d::Zero();  ///< f2 (N)
  Matrix3d stiffness = Matrix3d::Zero();   ///< ∂f2/∂d (N/m)
  Matrix3d damping = Matrix3d::Zero();     ///< ∂f2/∂ḋ (N s/m)
  double energy = 0.0;                     ///< stored energy U (J), ∫₀ᵉ T_s
  double tension = 0.0;                    ///< axial force −f2·n (N), tension positive
};

/// Spring-damper of natural length L0 (m) between P1 and P2, with d = r2 − r1 (m) and
/// ḋ = v2 − v1 (m/s).
///
/// L0 > 0 (a spring-damper along the line of its points): e = ρ − L0, n = d/ρ, ė = n·ḋ,
///   f2 = −T(e, ė) n,
/// with the regularised length ρ = √(|d|² + ε²), ε = 1e-8 L0. ρ differs from |d| by the relative
/// amount ε²/(2|d|²): under 5e-17 (rounding) for |d| ≥ L0, under 5e-13 for |d| ≥ L0/100. It
/// keeps everything finite as |d| → 0: at d = 0 the force is zero (an unstable equilibrium of a
/// crushed spring, whose direction is undefined) and the Jacobian ~ T/ε is large but finite.
/// U = ∫₀ᵉ T_s, and without damping f2 = −∂U/∂d exactly. Rigid rotation of the pair (ḋ ⟂ d)
/// gives ė = 0: damping dissipates nothing.
///
/// L0 = 0 (a knot link, the seed paper's T_i = K_i(δ_i) δ_i + b_i δ̇_i with δ a vector): with
/// ρ = |d| and the secant stiffness K(ρ) = T_s(ρ)/ρ,
///   f2 = −[K(ρ) d + b(ρ) ḋ],
/// and K(0) = dT_s/de at 0⁺, so the force is defined at d = 0. The damping is isotropic: it also
/// damps relative rotation of the pair (power −b |ω × d|²), as in the seed paper's model.
/// The law must give T_s(0) = 0 (no pretension in a zero-length link).
///
/// Throws InputError as ValidateSpringDamper does. Ma et al. (seed paper), "Cable nodes and their
/// connecting dynamics attribute modeling".
SpringDamperResult CalcSpringDamper(const ConnectionLaw& law, double natural_length,
                                    const Vector3d& d, const Vector3d& d_dot);

/// Throws InputError unless L0 (m) is non-negative and finite and, for L0 = 0, the law has no
/// pretension: |T_s(0)| ≤ 1e-12 times the largest force of its table (other kinds have
/// T_s(0) = 0). CalcSpringDamper checks this at every call; a model builder can call it once.
/// Does not re-validate the law itself (ValidateConnectionLaw does).
void ValidateSpringDamper(const ConnectionLaw& law, double natural_length);

}  // namespace ancfnet
