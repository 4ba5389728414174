#include "ancfnet/contact/laws/tangential_friction.hpp"

#include <stdexcept>

namespace ancfnet {

TangentialFriction CalcTangentialFriction(const FrictionLaw& law, const Vector3d& v_t,
                                          double normal_force) {
  if (law.kind == FrictionLawKind::kLuGre)
    throw std::logic_error("CalcTangentialFriction: the LuGre law keeps a bristle state");
  const double scale =
      law.kind == FrictionLawKind::kTanh ? law.regularization_speed : law.ramp_end_speed;
  const double speed = v_t.norm();
  TangentialFriction result;
  if (speed <= 1e-12 * scale) {
    // Isotropic limit: f ≈ F'(0) v.
    const FrictionForce at_rest = law.Evaluate(0.0, normal_force);
    result.force = at_rest.dforce_dvelocity * v_t;
    result.dforce_dvelocity = at_rest.dforce_dvelocity * Matrix3d::Identity();
    // Both regularised laws are proportional to N.
    if (normal_force > 0.0) result.dforce_dnormal = result.force / normal_force;
    return result;
  }
  const Vector3d direction = v_t / speed;
  const FrictionForce f = law.Evaluate(speed, normal_force);
  const Matrix3d along = direction * direction.transpose();
  result.force = f.force * direction;
  result.dforce_dvelocity =
      f.dforce_dvelocity * along + (f.force / speed) * (Matrix3d::Identity() - along);
  result.dforce_dnormal = f.dforce_dnormal * direction;
  return result;
}

}  // namespace ancfnet
