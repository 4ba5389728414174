#pragma once
/// @file Clearance joints (the description): a journal of radius R_J in a bearing of radius
/// R_B = R_J + c with radial clearance c > 0, each carried by the ground, a rigid body, a point
/// mass or a material point of an ANCF cable. A revolute clearance joint (planar) measures the
/// eccentricity in the plane normal to its axis, a spherical one (ball in socket) in space. The
/// forces are made by forces/clearance_joint_forces.hpp; docs/theory.md, "Clearance joints".

#include <array>
#include <optional>
#include <string>

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/laws/friction_law.hpp"
#include "ancfnet/contact/laws/normal_law.hpp"

namespace ancfnet {

/// What carries a journal or a bearing, and which of its points is the centre.
struct JointAnchor {
  enum class Kind {
    kGround,  ///< fixed in space at `ground_point`
    kBody,    ///< rigid body `body` at its point `body_point` (body frame), turning with it
    kPoint,   ///< a point mass or an ANCF material point: the blocks and weights below
  };
  Kind kind = Kind::kGround;
  Vector3d ground_point = Vector3d::Zero();  ///< kGround: the centre (m, world)
  Index body = -1;                           ///< kBody: index into Model::rigid_bodies()
  Vector3d body_point = Vector3d::Zero();    ///< kBody: s_B (m, body frame)
  /// kPoint: the centre c = Σ_b w_b q_b over 3-coordinate blocks (one block of weight 1 for a
  /// point mass; r_A, r'_A, r_B, r'_B with the Hermite shape values for a cable point).
  int num_blocks = 0;
  std::array<Index, 4> dof{};
  std::array<double, 4> weight{};
  /// kPoint on a cable: the slope r' = Σ_b w'_b q_b (dS/dx) at the point, whose turning
  /// ω = r' × ṙ'/|r'|² is the anchor's rotation (the cable carries no torsion). A point mass
  /// does not turn: `has_slope` false.
  bool has_slope = false;
  std::array<double, 4> slope_weight{};
};

/// A revolute (planar) or spherical clearance joint.
struct ClearanceJoint {
  enum class Type {
    kRevolute,   ///< e projected on the plane normal to `axis`
    kSpherical,  ///< e in space
  };
  std::string name;
  Type type = Type::kRevolute;
  JointAnchor journal;
  JointAnchor bearing;
  double clearance = 0.0;       ///< c = R_B − R_J (m), > 0
  double journal_radius = 0.0;  ///< R_J (m), > 0
  /// kRevolute: unit normal of the joint's plane, fixed in space (a planar mechanism's axis).
  Vector3d axis = Vector3d::UnitZ();
  /// The normal law of the internal contact. Its stiffness belongs to the joint's geometry: for
  /// a Hertz-type law k of the internal (conformal) contact, e.g. Lankarani & Nikravesh (1990)
  /// k = (4/3) E* √(R_J R_B/(R_B − R_J)) for a spherical pair.
  NormalLaw normal;
  /// Regularised friction (Ambrósio, tanh) on the slip at the contact point; none: frictionless.
  std::optional<FrictionLaw> friction;

  double bearing_radius() const { return journal_radius + clearance; }
};

}  // namespace ancfnet
