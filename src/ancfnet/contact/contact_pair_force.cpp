#include "ancfnet/contact/contact_pair_force.hpp"

#include <cmath>

#include "ancfnet/contact/laws/bristle_friction.hpp"
#include "ancfnet/contact/laws/tangential_friction.hpp"

namespace ancfnet {

ContactPairForce CalcContactPairForce(const NormalLaw& normal_law,
                                      const std::optional<FrictionLaw>& friction_law,
                                      const ContactKinematics& k, double approach_speed,
                                      const Vector3d& bristle, double step, bool with_jacobian) {
  ContactPairForce r;
  if (!(k.penetration > 0.0)) return r;
  const Vector3d& n = k.normal;
  const Vector3d& u = k.velocity;
  r.touching = true;
  r.penetration = k.penetration;
  r.rate = -n.dot(u);
  const NormalForce normal = normal_law.Evaluate(k.penetration, r.rate, std::abs(approach_speed));
  r.normal_force = normal.force;
  r.energy = normal_law.CalcElasticEnergy(k.penetration);
  r.force = normal.force * n;
  r.dissipative = (normal.force - normal.elastic_force) * n;
  // ∂f/∂δ, and the direction (n + ∂f_t/∂N) along which the normal force's changes act.
  Vector3d along = n;
  Matrix3d& df_dn = r.dforce_dnormal;
  if (with_jacobian) {
    df_dn = normal.force * Matrix3d::Identity();
    r.dforce_dv.setZero();
  }
  if (friction_law && normal.force > 0.0) {
    const Matrix3d tangent = Matrix3d::Identity() - n * n.transpose();
    TangentialFriction f;
    double df_dz = 0.0;  // ∂f_t/∂z₀ = df_dz I
    const Vector3d z0 = tangent * bristle;
    if (friction_law->kind == FrictionLawKind::kLuGre) {
      const TangentialBristleStep b =
          CalcTangentialBristleFriction(*friction_law, z0, tangent * u, normal.force, step);
      r.bristle = b.deflection;
      f = b.friction;
      df_dz = b.dforce_ddeflection;
    } else {
      f = CalcTangentialFriction(*friction_law, tangent * u, normal.force);
    }
    r.friction = f.force;
    r.force += f.force;
    r.dissipative += f.force;
    if (with_jacobian) {
      along += f.dforce_dnormal;
      r.dforce_dv = f.dforce_dvelocity * tangent;
      // The tangent plane turns with n: δ(P w) = −(n wᵀ + (n·w) I) δn for w = ẋ and w = z₀.
      df_dn -= f.dforce_dvelocity * (n * u.transpose() + n.dot(u) * Matrix3d::Identity());
      if (df_dz != 0.0) {
        df_dn -= df_dz * (n * bristle.transpose() + n.dot(bristle) * Matrix3d::Identity());
        r.dforce_dbristle = df_dz * tangent;
      }
    }
  }
  if (with_jacobian) {
    r.dforce_dv -= normal.dforce_ddelta_dot * along * n.transpose();
    df_dn -= normal.dforce_ddelta_dot * along * u.transpose();
    r.dforce_dx = -normal.dforce_ddelta * along * n.transpose() + df_dn * k.normal_derivative;
  }
  return r;
}

}  // namespace ancfnet
