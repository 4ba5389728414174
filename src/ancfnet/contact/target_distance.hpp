#pragma once
/// @file The narrow phase against a rigid target (contact/contact_spec.hpp): the signed distance of
/// a point to its surface, and the deepest point of a segment (a capsule's axis) in it, with the
/// outward normal and its derivative at the closest point (docs/theory.md, "Capsule chains
/// against rigid targets").

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/contact_spec.hpp"

namespace ancfnet {

/// Signed distance φ of a point to a target's surface (> 0 outside), the outward normal
/// n = ∂φ/∂x and H = ∂n/∂x.
struct TargetDistance {
  double distance = 0.0;                ///< φ (m)
  Vector3d normal = Vector3d::UnitZ();  ///< n
  Matrix3d hessian = Matrix3d::Zero();  ///< ∂n/∂x (1/m)
};

/// φ, n and ∂n/∂x of the point x for the target's shape, in the coordinates its geometry is
/// given in (the world, or its body's frame): contact/distance/point_*.hpp and MeshBvh.
TargetDistance CalcPointTargetDistance(const ContactTarget& target, const Vector3d& x);

/// A ball that holds a target, in the coordinates its distances are computed in (its body's frame
/// for a target on a body): every point farther than d from `center` is at least d − radius from
/// the target. A plane's radius is infinite.
struct TargetBoundingSphere {
  Vector3d center = Vector3d::Zero();
  double radius = 0.0;  ///< m
};
TargetBoundingSphere CalcTargetBoundingSphere(const ContactTarget& target);

/// The deepest point c(t*) = x₀ + t* (x₁ − x₀) of the segment [x₀, x₁] in the target:
/// t* = argmin φ(c(t)) over t ∈ [0, 1], by FindSegmentMinimum on φ(t), φ' = n·Δ,
/// φ'' = Δᵀ H Δ (Δ = x₁ − x₀) to |φ'| ≤ 10⁻¹² |Δ|. Convex targets (plane, sphere, box, cylinder,
/// capsule): φ is convex along the segment, one interval, the global minimum. Mesh (not convex):
/// four intervals, the local minimum next to the deepest of five samples. A zero-length segment
/// gives t* = 0, the point's distance.
struct SegmentTargetDistance : TargetDistance {
  double t = 0.0;       ///< t* ∈ [0, 1]
  int evaluations = 1;  ///< point queries made
  /// No more than the global minimum of φ on the segment (m): φ(c(t*)) for a convex target or a
  /// point; on a mesh, whose search may stop in a local minimum, the lowest of the m + 1 samples
  /// less |Δ|/(2m), as φ is 1-Lipschitz and every point of the segment lies within |Δ|/(2m) of a
  /// sample.
  double lower_bound = 0.0;
};
SegmentTargetDistance CalcSegmentTargetDistance(const ContactTarget& target, const Vector3d& x0,
                                                const Vector3d& x1);

}  // namespace ancfnet
