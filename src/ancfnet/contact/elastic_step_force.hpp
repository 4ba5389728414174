#pragma once
/// @file The elastic part of a contact force over a whole step, as a discrete gradient of the
/// contact's stored energy Φ(δ) (Gonzalez 1996, "Time integration and discrete Hamiltonian
/// systems", eq. 12; for contact: Laursen & Chawla 1997, Armero & Petőcz 1998). Its work over the
/// step equals the change of Φ exactly, whatever the step, including the steps in which a pair
/// touches or separates (docs/theory.md, "Energy-consistent contact").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/normal_law.hpp"

namespace ancfnet {

/// F̄ = (Φ(δ₁) − Φ(δ₀))/(δ₁ − δ₀) and ∂F̄/∂δ₁ (for the Newton iteration matrix), or the law's
/// elastic force at (δ₀ + δ₁)/2 and half its slope where δ₁ − δ₀ is at round-off level.
struct ElasticStepMagnitude {
  double force = 0.0;         ///< F̄ (N)
  double dforce_dend = 0.0;   ///< ∂F̄/∂δ₁ (N/m)
};
ElasticStepMagnitude CalcElasticStepMagnitude(const NormalLaw& law, double penetration_start,
                                              double penetration_end);

/// The elastic force f̄ on a probe over a step in which its penetration goes from δ₀ to δ₁ and
/// its contact point moves by d relative to the other body (d the displacement through which the
/// force's work is counted, Q·Δq = f̄·d), with n the unit normal at the middle of the step:
///   f̄ = F̄ n̄,   F̄ = (Φ(δ₁) − Φ(δ₀))/(δ₁ − δ₀),   n̄ = n + ((δ₀ − δ₁) − n·d)/|d|² d,
/// so that f̄·d = −(Φ(δ₁) − Φ(δ₀)). Where δ₁ − δ₀ is at round-off level F̄ is the law's elastic
/// force at (δ₀ + δ₁)/2, and where |d| is below `least_displacement` (m; callers use 10⁻⁶ of the
/// probe's radius) n̄ = n. Zero when neither end touches (δ ≤ 0).
Vector3d CalcElasticStepForce(const NormalLaw& law, double penetration_start,
                              double penetration_end, const Vector3d& normal,
                              const Vector3d& displacement, double least_displacement);

}  // namespace ancfnet
