#include "ancfnet/contact/laws/bristle_friction.hpp"

#include <stdexcept>

namespace ancfnet {

TangentialBristleStep CalcTangentialBristleFriction(const FrictionLaw& law, const Vector3d& z0,
                                                    const Vector3d& v, double normal_force,
                                                    double h) {
  if (law.kind != FrictionLawKind::kLuGre)
    throw std::logic_error("CalcTangentialBristleFriction: only a LuGre law has a bristle");
  if (!(h >= 0.0)) throw std::logic_error("CalcTangentialBristleFriction: negative step");
  const double s = v.norm();
  double dg = 0.0;
  const double g = law.CalcStribeck(s, &dg);
  const double sigma0 = law.bristle_stiffness;
  const double phi = sigma0 * s / g;
  const double dphi = sigma0 * (g - s * dg) / (g * g);
  const double den = 1.0 + h * phi;
  const Vector3d z_dot = (v - phi * z0) / den;
  TangentialBristleStep out;
  out.deflection = z0 + h * z_dot;
  Matrix3d dz_dot_dv = Matrix3d::Identity() / den;
  if (s > 0.0) dz_dot_dv -= (dphi / (den * s)) * out.deflection * v.transpose();
  const double n = normal_force > 0.0 ? normal_force : 0.0;
  const Vector3d bristle = sigma0 * out.deflection + law.bristle_damping * z_dot;
  TangentialFriction& f = out.friction;
  f.force = -n * bristle - law.viscous_damping * v;
  f.dforce_dvelocity = -n * (h * sigma0 + law.bristle_damping) * dz_dot_dv -
                       law.viscous_damping * Matrix3d::Identity();
  if (normal_force > 0.0) f.dforce_dnormal = -bristle;
  out.dforce_ddeflection = -n * (sigma0 - law.bristle_damping * phi) / den;
  return out;
}

}  // namespace ancfnet
