#pragma once
/// @file The primitives of self-contact and which pairs of them may touch. A primitive is a
/// capsule whose axis is the chord between two material points ξ₀ < ξ₁ of a cable element's
/// deformed centre line (a sphere when ξ₀ = ξ₁: an inspection sphere), or a point mass's sphere.
/// Pairs that are neighbours on one thread or meet at one knot are excluded (docs/theory.md,
/// "Self-contact").

#include <array>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

class Model;
struct Cable;

struct SelfContactPrimitive {
  Index element = -1;                  ///< cable element, or −1 for a point mass
  Index point_mass = -1;               ///< point mass, or −1
  Index cable = -1;                    ///< the element's cable, or −1
  double xi0 = 0.0, xi1 = 0.0;         ///< material coordinates of the axis' ends on the element
  Vector4d shape0 = Vector4d::Zero();  ///< S₁ … S₄ at ξ₀ (r = Σ S_k e_k)
  Vector4d shape1 = Vector4d::Zero();  ///< at ξ₁
  double radius = 0.0;                 ///< m
  double arc0 = 0.0, arc1 = 0.0;       ///< reference arc length of its ends along the cable (m)
  /// The coupling that carries its Jacobian blocks: the element, or num_elements + point mass.
  Index owner = 0;
  /// Capsules before and after it along its cable (sharing its ends ξ₀, ξ₁), or −1.
  int previous = -1, next = -1;
};

/// Capsules along every element (ContactSpec::self_geometry kCapsules; the automatic count is one
/// per 8 radii of element length, 1 … 8) or its inspection spheres (kSpheres, as the target
/// contact places them), then one sphere per point mass of radius point_mass_radius.
std::vector<SelfContactPrimitive> MakeSelfContactPrimitives(const Model& model);

/// Decides which pairs of primitives are left out: on one cable, those closer along it than
/// 2 (r_a + r_b) (neighbours, which touch by construction); across a junction (an ideal knot's
/// shared position, a point mass linked to thread ends, or such links chained), those on the two
/// elements that meet there (threads meeting at a knot fold onto each other about it freely),
/// and those whose arc distances to the junction add up to less than 2 (r_a + r_b).
class SelfContactFilter {
 public:
  SelfContactFilter(const Model& model, const std::vector<SelfContactPrimitive>& primitives);
  bool Excluded(int a, int b) const;

 private:
  // Distance along the primitive's cable from it to its cable's end `end` (0 or 1), or 0 for a
  // point mass's own junction.
  double ArcToEnd(const SelfContactPrimitive& p, int end) const;
  // Whether p lies on its cable's element at end `end` (a point mass: always).
  bool AtEndElement(const SelfContactPrimitive& p, int end) const;

  const std::vector<SelfContactPrimitive>* primitives_;
  const std::vector<Cable>* cables_;
  std::vector<double> cable_length_;
  std::vector<std::array<int, 2>> cable_end_junction_;  // junction of each cable end, −1 none
  std::vector<int> point_mass_junction_;
};

}  // namespace ancfnet
