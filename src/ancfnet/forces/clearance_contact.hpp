#pragma once
/// @file The contact inside a clearance joint from the motions of its journal and bearing
/// (forces/joint_anchor.hpp): eccentricity, penetration, the normal law and friction of
/// contact/contact_pair_force.hpp, and the friction moments about both centres, with their
/// derivatives. docs/theory.md, "Clearance joints"; Flores & Ambrósio (2004).

#include <Eigen/Core>

#include "ancfnet/model/clearance_joint.hpp"
#include "ancfnet/forces/joint_anchor.hpp"

namespace ancfnet {

/// Derivative of (f, m_J, m_B) with respect to a 3-vector.
using Matrix9x3d = Eigen::Matrix<double, 9, 3>;

/// The contact of a joint at one state. With P = I − a aᵀ (revolute, a the axis) or I
/// (spherical), x = c_J − c_B, the eccentricity e = P x, n = e/|e|, the penetration δ = |e| − c,
/// the contact point c_J + R_J n at r_B = x + R_J n from the bearing's centre, and the velocity
/// of the journal's material point there relative to the bearing's,
/// u = P (ċ_J − ċ_B + R_J ω_J × n − ω_B × r_B), with δ̇ = n·u. The law gives the force f on the
/// journal, −F_n n plus the friction f_t on the slip (I − n nᵀ) u (CalcContactPairForce with the
/// pair's normal −n), acting at the contact point: at the journal's centre f and the friction
/// moment m_J = R_J n × f, at the bearing's −f and m_B = −r_B × f (the same force at the same
/// point, so the moments balance; r_B × f has the friction moment (|e| + R_J) n × f_t and, for a
/// revolute joint whose centres are offset along the axis, that offset's couple).
///
/// With the LuGre law the bristle deflection z lives in the bearing's frame: a body bearing's
/// body frame, z_W = R_B z (it turns with the body, as target contact's bristle on a body
/// target), world axes for a ground or cable-point bearing (a cable point has a slope, not a
/// frame). CalcContactPairForce re-projects z_W on the current tangent plane and steps it over h.
struct ClearanceContact {
  bool touching = false;
  Vector3d eccentricity = Vector3d::Zero();    ///< e (m)
  Vector3d normal = Vector3d::UnitX();         ///< n = e/|e| (outward from the bearing's centre)
  double penetration = 0.0;                    ///< δ = |e| − c (m); < 0 in free flight
  double rate = 0.0;                           ///< δ̇ = n·u (m/s), > 0 approaching
  double normal_force = 0.0;                   ///< F_n (N)
  Vector3d force = Vector3d::Zero();           ///< f on the journal (N)
  Vector3d friction = Vector3d::Zero();        ///< f_t (N)
  Vector3d journal_moment = Vector3d::Zero();  ///< m_J about c_J (N m)
  Vector3d bearing_moment = Vector3d::Zero();  ///< m_B about c_B (N m)
  /// The damping and friction parts of f, m_J, m_B (for the dissipation account).
  Vector3d dissipative_force = Vector3d::Zero();
  Vector3d dissipative_journal_moment = Vector3d::Zero();
  Vector3d dissipative_bearing_moment = Vector3d::Zero();
  /// LuGre law: the bristle deflection z₁ (m) at the end of the step, in the bearing's frame (what
  /// UpdateClearanceJointHistory stores); else zero.
  Vector3d bristle = Vector3d::Zero();
  /// ∂(f, m_J, m_B)/∂c_J (= −∂/∂c_B), ∂/∂ċ_J (= −∂/∂ċ_B), ∂/∂ω_J and ∂/∂ω_B (with_jacobian).
  Matrix9x3d d_center = Matrix9x3d::Zero();
  Matrix9x3d d_velocity = Matrix9x3d::Zero();
  Matrix9x3d d_journal_omega = Matrix9x3d::Zero();
  Matrix9x3d d_bearing_omega = Matrix9x3d::Zero();
  /// ∂(f, m_J, m_B)/∂θ_B through the bristle of a body bearing, which turns with the body:
  /// δz_W = θ_B × z_W for a small rotation θ_B (world axes, δR_B = θ̃_B R_B); zero for other
  /// bearings and laws (with_jacobian).
  Matrix9x3d d_bearing_rotation = Matrix9x3d::Zero();
};

/// The eccentricity e = P (c_J − c_B) of the journal's centre c_J relative to the bearing's c_B.
Vector3d CalcEccentricity(const ClearanceJoint& joint, const Vector3d& journal_center,
                          const Vector3d& bearing_center);

/// The contact of `joint` with journal and bearing moving as given; `approach_speed` is the v₀
/// of its normal law (ContactPairHistory::speed), `bristle` the LuGre deflection z₀ at the start
/// of the step in the bearing's frame (ContactPairHistory::bristle) and `step` the step size h it
/// is advanced over (0: the force at the state, for outputs). Not touching (δ ≤ 0): no force and
/// z₁ = 0.
ClearanceContact CalcClearanceContact(const ClearanceJoint& joint, const AnchorMotion& journal,
                                      const AnchorMotion& bearing, double approach_speed,
                                      const Vector3d& bristle, double step, bool with_jacobian);

}  // namespace ancfnet
