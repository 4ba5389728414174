#include "ancfnet/contact/elastic_step_force.hpp"

#include <algorithm>
#include <cmath>

namespace ancfnet {

ElasticStepMagnitude CalcElasticStepMagnitude(const NormalLaw& law, double penetration_start,
                                              double penetration_end) {
  const double d0 = penetration_start;
  const double d1 = penetration_end;
  if (!(d0 > 0.0) && !(d1 > 0.0)) return {};
  // The divided difference of Φ loses about ε Φ/|δ₁ − δ₀| to round-off: below a change of 1e-8
  // of the penetration the tangent at the mean is as exact and free of it.
  const double change = d1 - d0;
  if (!(std::abs(change) > 1e-8 * std::max(std::abs(d0), std::abs(d1)))) {
    const NormalForce mean = law.Evaluate(0.5 * (d0 + d1), 0.0, 1.0);
    return {mean.elastic_force, 0.5 * mean.dforce_ddelta};
  }
  const double force = (law.CalcElasticEnergy(d1) - law.CalcElasticEnergy(d0)) / change;
  const double end_force = law.Evaluate(d1, 0.0, 1.0).elastic_force;
  return {force, (end_force - force) / change};
}

Vector3d CalcElasticStepForce(const NormalLaw& law, double penetration_start,
                              double penetration_end, const Vector3d& normal,
                              const Vector3d& displacement, double least_displacement) {
  const double d0 = penetration_start;
  const double d1 = penetration_end;
  const double magnitude = CalcElasticStepMagnitude(law, d0, d1).force;
  if (magnitude == 0.0) return Vector3d::Zero();
  // Below the least displacement the mismatch is the penetrations' round-off, which the division
  // by |d|² would turn into a spurious tangential force (a probe sticking on a slope); what n̄ = n
  // then leaves out of the energy is of order F̄ (|d|² κ + ε |x|), nothing.
  const double moved = displacement.squaredNorm();
  if (!(moved > least_displacement * least_displacement)) return magnitude * normal;
  const double mismatch = (d0 - d1) - normal.dot(displacement);
  return magnitude * (normal + (mismatch / moved) * displacement);
}

}  // namespace ancfnet
