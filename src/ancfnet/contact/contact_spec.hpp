#pragma once
/// @file Contact of the model's cables and point masses with rigid, fixed targets (a plane, a
/// sphere, a box, a cylinder, a capsule, a triangle mesh) and with each other: the description.
/// The forces are made by forces/target_contact.hpp and forces/self_contact.hpp. Cables are
/// probed by inspection spheres of the thread's radius at points along each element's centre
/// line, or by a chain of capsules of that radius whose axes are chords of the deformed centre
/// line; point masses are spheres.

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/friction_law.hpp"
#include "ancfnet/contact/laws/normal_law.hpp"
#include "ancfnet/contact/mesh/mesh_bvh.hpp"

namespace ancfnet {

/// A rigid target: fixed in space, or carried by a rigid body (`body`), its geometry then given in
/// the body's frame (origin x_WB, axes R_WB).
struct ContactTarget {
  enum class Kind { kPlane, kSphere, kBox, kCylinder, kCapsule, kMesh };
  Kind kind = Kind::kPlane;
  std::string name;
  Vector3d point = Vector3d::Zero();  ///< plane: a point of it; others: the centre (m)
  Vector3d normal =
      Vector3d::UnitZ();     ///< plane: outward unit normal; cylinder, capsule: unit axis
  double radius = 0.0;       ///< sphere, cylinder, capsule (m)
  double half_length = 0.0;  ///< cylinder (> 0), capsule (≥ 0): of the axis (m)
  Vector3d half_extents = Vector3d::Zero();  ///< box (m)
  Matrix3d rotation = Matrix3d::Identity();  ///< box: R_WB
  /// mesh: the surface in world coordinates (scale and pose applied when loaded), shared by the
  /// copies of a Model.
  std::shared_ptr<const MeshBvh> mesh;
  /// The rigid body carrying it (ModelBuilder::SetContact resolves the name; bodies must be
  /// added first), or "" / −1: fixed in space.
  std::string body_name;
  Index body = -1;
};

struct ContactSpec {
  std::vector<ContactTarget> targets;
  NormalLaw normal;
  /// Regularised laws (Ambrósio, tanh) or the LuGre bristle law (implicit integrators only);
  /// none: frictionless.
  std::optional<FrictionLaw> friction;
  /// Inspection spheres per cable element, at ξ = (j + ½)/n; 0: automatic, one per thread
  /// diameter of element length, between 2 and 32.
  int points_per_element = 0;
  /// Radius of the inspection spheres (m); 0: each cable's own section radius.
  double cable_radius = 0.0;
  double point_mass_radius = 0.0;  ///< m, ≥ 0
  /// Step control: a step is rejected (and cut) when an inspection sphere or point mass sinks
  /// into a target by more than this fraction of its radius within the step, so that impacts are
  /// resolved over several steps instead of absorbed in one; 0: no limit.
  double penetration_increment = 0.05;
  /// Geometry of the threads against the targets: inspection spheres (the default), or a chain
  /// of capsules_per_element capsules per element whose axes are the chords between
  /// ξ = j/n and (j + 1)/n of the deformed centre line (forces/target_contact.hpp).
  enum class TargetGeometry { kSpheres, kCapsules };
  TargetGeometry target_geometry = TargetGeometry::kSpheres;

  /// Contact of the threads with each other and with the point masses (knots), and of the
  /// point masses with each other (forces/self_contact.hpp).
  bool self_contact = false;
  /// Geometry of the threads in self-contact: a chain of capsules of the thread's radius along
  /// each element's deformed centre line, or its inspection spheres.
  enum class SelfGeometry { kCapsules, kSpheres };
  SelfGeometry self_geometry = SelfGeometry::kCapsules;
  /// Capsules per cable element, in self-contact and against targets; 0: automatic, one per
  /// 8 radii of element length, 1 … 8.
  int capsules_per_element = 0;

  bool enabled() const { return !targets.empty() || self_contact; }
};

/// Inspection spheres on a cable element of length L (m) and thread radius r (m):
/// points_per_element, or ⌈L/2r⌉ clamped to 2 … 32 (2 for r = 0).
inline int CalcSpheresPerElement(const ContactSpec& spec, double length, double radius) {
  if (spec.points_per_element > 0) return spec.points_per_element;
  if (!(radius > 0.0)) return 2;
  return static_cast<int>(std::clamp(std::ceil(length / (2.0 * radius)), 2.0, 32.0));
}

/// Capsules on a cable element: capsules_per_element, or ⌈L/8r⌉ clamped to 1 … 8 (1 for r = 0).
inline int CalcCapsulesPerElement(const ContactSpec& spec, double length, double radius) {
  if (spec.capsules_per_element > 0) return spec.capsules_per_element;
  if (!(radius > 0.0)) return 1;
  return static_cast<int>(std::clamp(std::ceil(length / (8.0 * radius)), 1.0, 8.0));
}

}  // namespace ancfnet
