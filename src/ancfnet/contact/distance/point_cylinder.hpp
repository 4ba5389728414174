#pragma once
/// @file Signed distance of a point to a finite solid cylinder (a rigid target, the capstan
/// drum), with the outward normal and the Hessian; the gap of a sphere of radius r is
/// distance − r.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Which part of the cylinder's surface holds the closest point.
enum class CylinderRegion {
  kSide,  ///< the curved surface
  kCap,   ///< one of the flat ends
  kRim,   ///< a circular edge (outside only)
};

/// Signed distance of a point to a cylinder and its derivatives with respect to the point.
struct PointCylinderDistance {
  double distance = 0.0;   ///< φ (m): > 0 outside, < 0 inside
  Vector3d closest_point;  ///< nearest point of the surface (m)
  Vector3d normal;         ///< outward unit normal n = ∂φ/∂p, p = x + φ n
  Matrix3d hessian;        ///< ∂²φ/∂p² (1/m)
  CylinderRegion region = CylinderRegion::kSide;
  bool inside = false;  ///< φ ≤ 0
};

/// Signed distance of the point p to the cylinder of centre c, unit axis a, radius ρ > 0 and
/// half length H > 0 (m). With z = a·(p − c), the radial vector v = p − c − z a, ρ_p = |v|,
/// e_r = v/ρ_p, σ = sign z, δr = ρ_p − ρ and δz = |z| − H (a 2-D box problem in (ρ_p, z)):
///   side (δr > 0 ≥ δz, or inside with δr ≥ δz): φ = δr, n = e_r, ∂²φ/∂p² = P/ρ_p with
///     P = I − a aᵀ − e_r e_rᵀ;
///   cap (δz > 0 ≥ δr, or inside with δz > δr): φ = δz, n = σ a, Hessian 0;
///   rim (δr, δz > 0): φ = √(δr² + δz²), n = (δr e_r + δz σ a)/φ,
///     ∂²φ/∂p² = (e_r e_rᵀ + a aᵀ − n nᵀ + δr P/ρ_p)/φ.
/// Degenerate input: on the axis (ρ_p ≤ 10⁻¹² ρ) e_r is a fixed perpendicular of a
/// (AnyUnitPerpendicular) and the P/ρ_p terms are dropped; σ = +1 for z = 0. Precondition:
/// |a| = 1 (not checked).
PointCylinderDistance CalcPointCylinderDistance(const Vector3d& p, const Vector3d& center,
                                                const Vector3d& axis, double radius,
                                                double half_length);

}  // namespace ancfnet
