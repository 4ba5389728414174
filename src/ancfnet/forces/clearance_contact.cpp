#include "ancfnet/forces/clearance_contact.hpp"

#include "ancfnet/contact/contact_pair_force.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"

namespace ancfnet {
namespace {

// Rows (f, m_J, m_B) of the derivative with respect to one input, from ∂f, ∂n and ∂r_B:
// m_J = R_J n × f, m_B = −r_B × f.
Matrix9x3d StackMoments(const Matrix3d& df, const Matrix3d& dn, const Matrix3d& dr,
                        const Vector3d& n, const Vector3d& f, double journal_radius,
                        const Vector3d& r_B) {
  Matrix9x3d out;
  const Matrix3d f_skew = Skew(f);
  out.topRows<3>() = df;
  out.middleRows<3>(3) = journal_radius * (Skew(n) * df - f_skew * dn);
  out.bottomRows<3>() = -Skew(r_B) * df + f_skew * dr;
  return out;
}

// P = I − a aᵀ of a revolute joint, I of a spherical one.
Matrix3d Projection(const ClearanceJoint& joint) {
  if (joint.type == ClearanceJoint::Type::kSpherical) return Matrix3d::Identity();
  return Matrix3d::Identity() - joint.axis * joint.axis.transpose();
}

// The rotation from the frame the joint's bristle is stored in to the world: a body bearing's
// R_B, else I (ClearanceContact).
Matrix3d BristleFrame(const AnchorMotion& bearing) {
  return bearing.kind == JointAnchor::Kind::kBody ? bearing.rotation : Matrix3d::Identity();
}

}  // namespace

Vector3d CalcEccentricity(const ClearanceJoint& joint, const Vector3d& journal_center,
                          const Vector3d& bearing_center) {
  return Projection(joint) * (journal_center - bearing_center);
}

ClearanceContact CalcClearanceContact(const ClearanceJoint& joint, const AnchorMotion& journal,
                                      const AnchorMotion& bearing, double approach_speed,
                                      const Vector3d& bristle, double step, bool with_jacobian) {
  ClearanceContact r;
  const Matrix3d plane = Projection(joint);
  const Vector3d x = journal.center - bearing.center;
  r.eccentricity = plane * x;
  const double d = r.eccentricity.norm();
  r.penetration = d - joint.clearance;
  if (!(r.penetration > 0.0)) return r;
  const Vector3d n = r.eccentricity / d;
  const double radius = joint.journal_radius;
  // The contact point P = c_J + R_J n seen from the bearing's centre: r_B = x + R_J n (with the
  // axial offset (I − P) x of a revolute joint, so that the moments balance).
  const Vector3d r_B = x + radius * n;
  const Matrix3d dn = (plane - n * n.transpose()) / d;  // ∂n/∂x
  const Vector3d& w_j = journal.angular_velocity;
  const Vector3d& w_b = bearing.angular_velocity;
  const Vector3d u =
      plane * (journal.velocity - bearing.velocity + radius * w_j.cross(n) - w_b.cross(r_B));
  // The bristle in world axes, z_W = R z (ClearanceContact), stepped over h by the pair's law.
  const Matrix3d frame = BristleFrame(bearing);
  const Vector3d bristle_w = frame * bristle;
  const ContactPairForce pair = CalcContactPairForce(
      joint.normal, joint.friction,
      {.penetration = r.penetration, .normal = -n, .normal_derivative = -dn, .velocity = u},
      approach_speed, bristle_w, step, with_jacobian);
  r.touching = true;
  r.normal = n;
  r.rate = pair.rate;
  r.normal_force = pair.normal_force;
  r.force = pair.force;
  r.friction = pair.friction;
  r.journal_moment = radius * n.cross(pair.force);
  r.bearing_moment = -r_B.cross(pair.force);
  r.dissipative_force = pair.dissipative;
  r.dissipative_journal_moment = radius * n.cross(pair.dissipative);
  r.dissipative_bearing_moment = -r_B.cross(pair.dissipative);
  r.bristle = frame.transpose() * pair.bristle;
  if (!with_jacobian) return r;
  const Matrix3d& f_u = pair.dforce_dv;
  const Matrix3d dr = Matrix3d::Identity() + radius * dn;  // ∂r_B/∂x
  const Matrix3d du_dx = plane * (radius * Skew(w_j) * dn - Skew(w_b) * dr);
  const Matrix3d zero = Matrix3d::Zero();
  const Vector3d& f = pair.force;
  r.d_center = StackMoments(pair.dforce_dx + f_u * du_dx, dn, dr, n, f, radius, r_B);
  r.d_velocity = StackMoments(f_u * plane, zero, zero, n, f, radius, r_B);
  r.d_journal_omega = StackMoments(-radius * f_u * plane * Skew(n), zero, zero, n, f, radius, r_B);
  r.d_bearing_omega = StackMoments(f_u * plane * Skew(r_B), zero, zero, n, f, radius, r_B);
  // A body bearing's bristle turns with it: δz_W = θ_B × z_W = −z̃_W θ_B.
  if (bearing.kind == JointAnchor::Kind::kBody)
    r.d_bearing_rotation =
        StackMoments(-pair.dforce_dbristle * Skew(bristle_w), zero, zero, n, f, radius, r_B);
  return r;
}

}  // namespace ancfnet
