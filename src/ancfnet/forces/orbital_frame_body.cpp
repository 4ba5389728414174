#include "ancfnet/forces/orbital_frame_body.hpp"

#include "ancfnet/common/skew.hpp"
#include "ancfnet/forces/orbital_frame.hpp"

namespace ancfnet {

HillBodyTerms CalcHillBodyTerms(double mass, const Matrix3d& inertia, const BodyPose& pose,
                                const BodyVelocity& velocity, double mean_motion) {
  const double n = mean_motion;
  const Matrix3d& j = inertia;
  const Vector3d& x = pose.p_WB;
  const Vector3d& w = velocity.w_B;
  const Vector3d radial = pose.R_WB.transpose() * Vector3d::UnitX();     // ê
  const Vector3d orbit = n * pose.R_WB.transpose() * Vector3d::UnitZ();  // Ω_B
  const Vector3d jw = j * w;
  const Vector3d j_orbit = j * orbit;
  const Vector3d j_radial = j * radial;
  HillBodyTerms t;
  t.force = -mass * (CalcHillStiffness(n) * x + CalcHillGyroscopic(n) * velocity.v_WB);
  t.moment = -j * w.cross(orbit) + w.cross(j_orbit) + orbit.cross(jw) + orbit.cross(j_orbit) -
             3.0 * n * n * radial.cross(j_radial);
  // δu_B = u_B × δθ for a direction fixed in Hill axes (ê, and Ω_B), so for −k u × J u:
  // ∂/∂θ = k ((J u)~ − ũ J) ũ, with k = −1 for Ω (Ω × J Ω) and 3n² for ê.
  const Matrix3d s_orbit = Skew(orbit);
  const Matrix3d s_radial = Skew(radial);
  const Matrix3d s_w = Skew(w);
  t.moment_rotation = (-j * s_w + s_w * j - Skew(jw)) * s_orbit -
                      (Skew(j_orbit) - s_orbit * j) * s_orbit +
                      3.0 * n * n * (Skew(j_radial) - s_radial * j) * s_radial;
  t.moment_rate = j * s_orbit - Skew(j_orbit) + s_orbit * j;
  return t;
}

double CalcHillBodyPotential(double mass, const Matrix3d& inertia, const BodyPose& pose,
                             double mean_motion) {
  const double n = mean_motion;
  const Vector3d radial = pose.R_WB.transpose() * Vector3d::UnitX();
  const Vector3d orbit = n * pose.R_WB.transpose() * Vector3d::UnitZ();
  return -0.5 * mass * pose.p_WB.dot(CalcHillStiffness(n) * pose.p_WB) +
         1.5 * n * n * radial.dot(inertia * radial) - 0.5 * orbit.dot(inertia * orbit);
}

}  // namespace ancfnet
