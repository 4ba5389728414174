#include "ancfnet/forces/spring_damper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

// ε / L0 of the regularised length ρ = √(|d|² + ε²) of a spring with L0 > 0.
constexpr double kSoftLengthFraction = 1e-8;
// Below this |d| (m) a zero-length link uses its limit K(0) = dT_s/de at 0⁺: d/|d| would lose
// all precision (|d|² underflows).
constexpr double kTinyLength = 1e-150;
// A zero-length link tolerates |T_s(0)| up to this fraction of the table's largest force (the
// rounding of an interpolation that passes through the origin).
constexpr double kPretensionTolerance = 1e-12;

// L0 > 0: f2 = −T(e, ė) n along the regularised direction n = d/ρ.
SpringDamperResult CalcAxial(const ConnectionLaw& law, double natural_length, const Vector3d& d,
                             const Vector3d& d_dot) {
  const double eps = kSoftLengthFraction * natural_length;
  const double rho = std::sqrt(d.squaredNorm() + eps * eps);
  const Vector3d n = d / rho;
  const double e = rho - natural_length;
  const double e_dot = n.dot(d_dot);
  const ConnectionForce t = law.Evaluate(e, e_dot);
  // ∂n/∂d = (I − n nᵀ)/ρ, ∂ė/∂d = (I − n nᵀ) ḋ/ρ, ∂e/∂d = n, ∂ė/∂ḋ = n.
  const Matrix3d projector = Matrix3d::Identity() - n * n.transpose();
  const Vector3d de_dot_dd = projector * d_dot / rho;
  SpringDamperResult r;
  r.force_on_2 = -t.force * n;
  r.stiffness = -(t.dforce_de * n * n.transpose() + t.dforce_dedot * n * de_dot_dd.transpose() +
                  (t.force / rho) * projector);
  r.damping = -t.dforce_dedot * n * n.transpose();
  r.energy = law.CalcEnergy(e);
  r.tension = t.force;
  return r;
}

// L0 = 0: f2 = −[K(ρ) d + b(ρ) ḋ], K = T_s(ρ)/ρ.
SpringDamperResult CalcIsotropic(const ConnectionLaw& law, const Vector3d& d,
                                 const Vector3d& d_dot) {
  const double rho = d.norm();
  SpringDamperResult r;
  r.energy = law.CalcEnergy(rho);
  if (rho < kTinyLength) {
    const double k0 = law.CalcSpring(kTinyLength).stiffness;
    const double b0 = law.CalcDamping(kTinyLength).coefficient;
    r.force_on_2 = -(k0 * d + b0 * d_dot);
    r.stiffness = -k0 * Matrix3d::Identity();
    r.damping = -b0 * Matrix3d::Identity();
    return r;
  }
  const Vector3d n = d / rho;
  const SpringTerms s = law.CalcSpring(rho);
  const DampingTerms b = law.CalcDamping(rho);
  const double secant = s.force / rho;
  r.force_on_2 = -(secant * d + b.coefficient * d_dot);
  // ∂(K d)/∂d = K I + (dT_s/de − K) n nᵀ; ∂(b ḋ)/∂d = (db/de) ḋ nᵀ.
  r.stiffness = -(secant * Matrix3d::Identity() + (s.stiffness - secant) * n * n.transpose() +
                  b.dcoefficient_de * d_dot * n.transpose());
  r.damping = -b.coefficient * Matrix3d::Identity();
  r.tension = -r.force_on_2.dot(n);
  return r;
}

}  // namespace

void ValidateSpringDamper(const ConnectionLaw& law, double natural_length) {
  if (!(std::isfinite(natural_length) && natural_length >= 0.0))
    throw InputError(fmt::format(
        "spring-damper: natural length must be non-negative and finite (got {})", natural_length));
  if (natural_length > 0.0 || law.spring != SpringKind::kPiecewiseLinear) return;
  double scale = 0.0;
  for (const ForceTablePoint& point : law.table) scale = std::max(scale, std::abs(point.force));
  const double pretension = law.CalcSpring(0.0).force;
  if (std::abs(pretension) > kPretensionTolerance * scale)
    throw InputError(
        fmt::format("spring-damper: a zero-length link needs a force table with zero force at zero "
                    "elongation (got {} N)",
                    pretension));
}

SpringDamperResult CalcSpringDamper(const ConnectionLaw& law, double natural_length,
                                    const Vector3d& d, const Vector3d& d_dot) {
  ValidateSpringDamper(law, natural_length);
  return natural_length > 0.0 ? CalcAxial(law, natural_length, d, d_dot)
                              : CalcIsotropic(law, d, d_dot);
}

}  // namespace ancfnet
