#pragma once
/// @file Signed distance of a point to a sphere, with the gradient and the Hessian that the
/// stiffness of a contact force on a curved target needs.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Signed distance of a point to a sphere and its derivatives with respect to the point.
struct PointSphereDistance {
  double distance = 0.0;   ///< d = |p − c| − R (m), negative inside
  Vector3d normal;         ///< n = (p − c)/|p − c| = ∂d/∂p, outward, unit
  Vector3d closest_point;  ///< c + R n, on the sphere (m)
  Matrix3d hessian;        ///< ∂²d/∂p² = (I − n nᵀ)/|p − c| (1/m)
  bool at_center = false;  ///< true where |p − c| ≤ 10⁻¹² R: n = e_z and the Hessian is 0
};

/// Signed distance d = |p − c| − R of the point p to the sphere of centre c and radius R ≥ 0
/// (m), with ∂d/∂p = n and ∂²d/∂p² = (I − n nᵀ)/|p − c|. Degenerate input: where
/// |p − c| ≤ 10⁻¹² max(R, 10⁻³⁰⁰) the direction is lost; the function then returns n = e_z,
/// the closest point c + R e_z, d = |p − c| − R and a zero Hessian (the 1/|p − c| term is
/// unbounded there; a zero value keeps an iteration matrix finite). docs/theory.md, "Contact
/// distance functions".
PointSphereDistance CalcPointSphereDistance(const Vector3d& p, const Vector3d& c, double radius);

}  // namespace ancfnet
