#pragma once
/// @file Where a contact capsule's axis is: the one geometry of the probes against targets
/// (model/contact_probes.hpp) and of the primitives of self-contact
/// (forces/self_contact_primitives.hpp).

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// A capsule's axis from x₀ to x₁ (m) and the velocities of its ends (m/s); a sphere has x₀ = x₁.
struct CapsuleAxis {
  Vector3d x0, x1, v0, v1;
};

/// The axis of a capsule `c` carried by the point mass c.point_mass (where c.element < 0) or by the
/// cable element c.element between the two points whose shape-function values are c.shape0 and
/// c.shape1 (r = Σ_k S_k e_k; equal for a sphere): its ends at the positions q and, given
/// velocities v, their velocities (else zero).
template <class Capsule>
CapsuleAxis LocateCapsuleAxis(const Model& model, const Capsule& c, const VectorXd& q,
                              const VectorXd* v = nullptr) {
  CapsuleAxis axis;
  axis.v0.setZero();
  axis.v1.setZero();
  if (c.element < 0) {
    const Index dof = model.point_masses()[c.point_mass].dof;
    axis.x0 = axis.x1 = q.template segment<3>(dof);
    if (v) axis.v0 = axis.v1 = v->template segment<3>(dof);
    return axis;
  }
  const CableElement& element = model.elements()[c.element];
  const auto interpolate = [&](const Vector4d& shape, const VectorXd& values) {
    Vector3d x = Vector3d::Zero();
    for (int k = 0; k < 4; ++k) x += shape[k] * values.template segment<3>(element.dofs[3 * k]);
    return x;
  };
  const bool sphere = c.shape0 == c.shape1;
  axis.x0 = interpolate(c.shape0, q);
  axis.x1 = sphere ? axis.x0 : interpolate(c.shape1, q);
  if (v) {
    axis.v0 = interpolate(c.shape0, *v);
    axis.v1 = sphere ? axis.v0 : interpolate(c.shape1, *v);
  }
  return axis;
}

}  // namespace ancfnet
