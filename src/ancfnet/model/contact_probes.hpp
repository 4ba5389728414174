#pragma once
/// @file The contact probes of a model against its rigid targets (contact/contact_spec.hpp):
/// inspection spheres or capsule chains along each cable element and one sphere per point mass,
/// fixed by the model's description. The forces on them are made by forces/target_contact.hpp.

#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// A probe of a cable element: a capsule whose axis is the chord between the material points
/// ξ₀ < ξ₁ of the deformed centre line, c(t) = (1 − t) r(ξ₀) + t r(ξ₁), or an inspection sphere
/// (ξ₀ = ξ₁); or a point mass's sphere.
struct ContactProbe {
  Index element = -1;                  ///< cable element, or −1 for a point mass
  Index point_mass = -1;               ///< point mass, or −1
  double xi0 = 0.0, xi1 = 0.0;         ///< ξ ∈ [0, 1] of the axis' ends on the element
  Vector4d shape0 = Vector4d::Zero();  ///< S₁ … S₄ at ξ₀ (r = Σ S_k e_k)
  Vector4d shape1 = Vector4d::Zero();  ///< at ξ₁
  double radius = 0.0;                 ///< m
};

/// The probes of the model in order: for each cable element its inspection spheres at
/// ξ = (j + ½)/n (ContactSpec::TargetGeometry::kSpheres) or its capsules from ξ = j/n to
/// (j + 1)/n (kCapsules), then one sphere per point mass. Empty without contact targets.
std::vector<ContactProbe> MakeContactProbes(const Model& model);

/// Number of (probe, target) pairs: the size of State::contact_history.
Index CountContactPairs(const Model& model);

}  // namespace ancfnet
