#pragma once
/// @file A box that holds a cable element's whole centre line, for culls that skip every contact
/// probe of an element at once (forces/target_contact.cpp).

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/broad_phase/aabb.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// The box of element `e`'s centre line at the positions q. The cubic Hermite curve
/// r(ξ) = S₁ r_A + L S₂ r′_A + S₃ r_B + L S₄ r′_B is the Bézier curve of the control points
/// r_A, r_A + (L/3) r′_A, r_B − (L/3) r′_B, r_B, and lies in their convex hull (Farin, Curves and
/// Surfaces for CAGD, 5th ed., §4.2), hence in their box; so does every segment between two of
/// its points (a capsule's axis).
inline Aabb CalcCableElementBox(const Model& model, Index e, const VectorXd& q) {
  const CableElement& element = model.elements()[e];
  const double third = element.parameters.length / 3.0;
  const auto block = [&](int k) { return q.segment<3>(element.dofs[3 * k]); };
  const Vector3d p0 = block(0), p3 = block(2);
  const Vector3d p1 = p0 + third * block(1), p2 = p3 - third * block(3);
  return {p0.cwiseMin(p1).cwiseMin(p2).cwiseMin(p3), p0.cwiseMax(p1).cwiseMax(p2).cwiseMax(p3)};
}

}  // namespace ancfnet
