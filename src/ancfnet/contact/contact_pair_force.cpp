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
  r.touching = true;
  r.penetration = k.penetration;
  r.rate = -n.dot(k.velocity);
  const NormalForce normal = normal_law.Evaluate(k.penetration, r.rate, std::abs(approach_speed));
  r.normal_force = normal.force;
  r.energy = normal_law.CalcElasticEnergy(k.penetration);
  r.force = normal.force * n;
  r.dissipative = (normal.force - normal.elastic_force) * n;
  const Eigen::RowVector3d dF_dx =
      -normal.dforce_ddelta * n.transpose() -
      normal.dforce_ddelta_dot * (k.normal_derivative * k.velocity).transpose();
  const Eigen::RowVector3d dF_dv = -normal.dforce_ddelta_dot * n.transpose();
  if (with_jacobian) {
    r.dforce_dx = n * dF_dx + normal.force * k.normal_derivative;
    r.dforce_dv = n * dF_dv;
  }
  if (friction_law && normal.force > 0.0) {
    const Matrix3d tangent = Matrix3d::Identity() - n * n.transpose();
    TangentialFriction f;
    if (friction_law->kind == FrictionLawKind::kLuGre) {
      const TangentialBristleStep b = CalcTangentialBristleFriction(
          *friction_law, tangent * bristle, tangent * k.velocity, normal.force, step);
      r.bristle = b.deflection;
      f = b.friction;
    } else {
      f = CalcTangentialFriction(*friction_law, tangent * k.velocity, normal.force);
    }
    r.friction = f.force;
    r.force += f.force;
    r.dissipative += f.force;
    if (with_jacobian) {
      r.dforce_dv += f.dforce_dvelocity * tangent + f.dforce_dnormal * dF_dv;
      r.dforce_dx += f.dforce_dnormal * dF_dx;
    }
  }
  return r;
}

}  // namespace ancfnet
