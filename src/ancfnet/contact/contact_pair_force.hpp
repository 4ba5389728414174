#pragma once
/// @file The force of one contact pair from its penetration, normal and relative velocity: the
/// normal law plus regularised friction, with the derivatives an implicit integrator needs. Shared
/// by the contact with rigid targets and the self-contact of threads (docs/theory.md, "Contact
/// with rigid targets" and "Self-contact").

#include <optional>

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/friction_law.hpp"
#include "ancfnet/contact/laws/normal_law.hpp"

namespace ancfnet {

/// Where a pair stands: the penetration δ = r − g of a probe of radius r at gap g, the unit
/// normal n pushing the probe out (from the other body towards it), ∂n/∂x, and the velocity ẋ of
/// the probe relative to the other body. x is the probe's position relative to the other body.
struct ContactKinematics {
  double penetration = 0.0;                       ///< δ (m), > 0 when touching
  Vector3d normal = Vector3d::UnitZ();            ///< n
  Matrix3d normal_derivative = Matrix3d::Zero();  ///< ∂n/∂x (1/m)
  Vector3d velocity = Vector3d::Zero();           ///< ẋ (m/s)
};

/// The force f on the probe and its derivatives: with respect to x and ẋ, and the partial ones
/// with respect to n and to the bristle deflection z₀ that a pair on a moving body needs (its
/// normal and bristle turn with the body).
struct ContactPairForce {
  bool touching = false;
  double penetration = 0.0;                 ///< δ (m)
  double rate = 0.0;                        ///< δ̇ = −n·ẋ (m/s), > 0 approaching
  double normal_force = 0.0;                ///< F_n (N)
  double energy = 0.0;                      ///< ∫ F_elastic dδ (J)
  Vector3d force = Vector3d::Zero();        ///< f = F_n n + f_t (N)
  Vector3d dissipative = Vector3d::Zero();  ///< its damping and friction part (N)
  Vector3d friction = Vector3d::Zero();     ///< f_t (N)
  Matrix3d dforce_dx = Matrix3d::Zero();  ///< ∂f/∂x = −(∂f/∂δ) nᵀ + (∂f/∂n) ∂n/∂x
  Matrix3d dforce_dv = Matrix3d::Zero();        ///< ∂f/∂ẋ
  Matrix3d dforce_dnormal = Matrix3d::Zero();   ///< ∂f/∂n at fixed δ, ẋ, z₀ (N)
  Matrix3d dforce_dbristle = Matrix3d::Zero();  ///< ∂f/∂z₀ (N/m), LuGre only
  /// LuGre law: the bristle deflection z₁ (m) at the end of the step; else zero.
  Vector3d bristle = Vector3d::Zero();
};

/// F_n = law(δ, δ̇, v₀) along n plus friction on the tangential velocity v_t = P ẋ,
/// P = I − n nᵀ: a regularised law (tangential_friction.hpp), or the LuGre bristle
/// (bristle_friction.hpp) stepped over h from the pair's deflection z₀ re-projected onto the
/// current tangent plane, P z₀ (h = 0: the force at the state, for outputs). The derivatives are
/// complete (docs/theory.md, "Complete contact Jacobians"): with δ̇ = −n·ẋ,
///   ∂f/∂δ = F_δ (n + ∂f_t/∂N),   ∂f/∂ẋ = −F_δ̇ (n + ∂f_t/∂N) nᵀ + (∂f_t/∂v_t) P,
///   ∂f/∂n = F I − F_δ̇ (n + ∂f_t/∂N) ẋᵀ − (∂f_t/∂v_t)(n ẋᵀ + (n·ẋ) I)
///           − (∂f_t/∂z₀)(n z₀ᵀ + (n·z₀) I),   (the turning of the tangent plane: δ(P w) =
///   −(n wᵀ + (n·w) I) δn), ∂f/∂z₀ = (∂f_t/∂z₀) P, and ∂f/∂x = −(∂f/∂δ) nᵀ + (∂f/∂n) ∂n/∂x.
/// `approach_speed` is v₀ (its absolute value is used). Not touching (δ ≤ 0), or pressing with
/// no force: no friction and z₁ = 0; not touching: all zero.
ContactPairForce CalcContactPairForce(const NormalLaw& normal_law,
                                      const std::optional<FrictionLaw>& friction_law,
                                      const ContactKinematics& kinematics, double approach_speed,
                                      const Vector3d& bristle, double step, bool with_jacobian);

}  // namespace ancfnet
