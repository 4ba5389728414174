#pragma once
/// @file The Model: what is simulated (topology, parameters, coordinate numbering, loads, boundary
/// conditions, initial state). Built once by ModelBuilder, read-only afterwards.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/contact/contact_spec.hpp"
#include "ancfnet/elements/ancf_beam.hpp"
#include "ancfnet/elements/ancf_cable.hpp"
#include "ancfnet/elements/connection_law.hpp"
#include "ancfnet/model/clearance_joint.hpp"
#include "ancfnet/model/damping_spec.hpp"
#include "ancfnet/model/ideal_joint.hpp"
#include "ancfnet/model/material.hpp"
#include "ancfnet/model/prescribed_motion.hpp"
#include "ancfnet/model/rigid_body.hpp"

namespace ancfnet {

/// The element a cable is made of: the gradient-deficient cable (elements/ancf_cable.hpp) or the
/// shear-deformable, torsional beam (elements/ancf_beam.hpp).
enum class ElementKind { kCable, kBeam };

/// A cable: a chain of ANCF elements between consecutive nodes.
struct Cable {
  std::string name;
  Index first_node = 0;     ///< nodes first_node … first_node + num_elements
  Index first_element = 0;  ///< elements first_element … first_element + num_elements − 1
  Index num_elements = 0;
  double length = 0.0;  ///< reference (natural, stress-free) length (m)
  CableProperties properties;
  /// Tension (N) at which the cable fails: every link holding it then breaks (analysis/
  /// failure.hpp). Infinite: never.
  double breaking_force = std::numeric_limits<double>::infinity();
  ElementKind element = ElementKind::kCable;
};

/// Where the coordinates of a cable node live: its position r (3 coordinates from
/// position_dof), which an ideal knot shares with the other threads meeting there, and its
/// slope r' (3 coordinates from slope_dof), shared only with a cable that continues this one
/// (CableSpec::start_cable). A beam node adds the section gradients r_y, r_z (6 coordinates from
/// section_dof); a cable element on the same node uses only r and r' (docs/theory.md, "Beams in
/// a model").
struct CableNode {
  Index position_dof = 0;
  Index slope_dof = 0;
  Index section_dof = -1;  ///< r_y then r_z of a beam node; −1 for a cable node
};

/// A concentrated mass with three position coordinates: a knot, a bullet, any lumped mass.
struct PointMass {
  std::string name;
  double mass = 0.0;  ///< kg, ≥ 0
  Index dof = 0;      ///< first of its 3 coordinates
};

/// One ANCF cable element and where its 12 coordinates live in the global vector.
/// For an element of a beam cable it is the beam's centre line: the same cubic Hermite in
/// (r_A, r_x,A, r_B, r_x,B), with the beam's length and ρA, so that loads, gravity, the
/// translational mass, contact and outputs treat both kinds alike; its stiffness is then the
/// beam element's `beam` (CalcInternalForces skips the cable kernel).
struct CableElement {
  Index cable = 0;
  std::array<Index, kCableElementDofs> dofs{};
  CableElementParameters parameters;
  Index beam = -1;  ///< index in Model::beam_elements(), or −1 for a cable element
};

/// One ANCF beam element: where its 24 coordinates [r_A, r_x,A, r_y,A, r_z,A, r_B, …] live.
struct BeamElement {
  Index element = 0;  ///< its centre line in Model::elements()
  std::array<Index, kBeamElementDofs> dofs{};
  BeamElementParameters parameters;
};

/// A material point of a cable: element and local coordinate ξ ∈ [0, 1].
struct MaterialPoint {
  Index element = 0;
  double xi = 0.0;
};

/// A point whose position is a fixed combination of 3-coordinate blocks, r = Σ_b w_b q_b: a cable
/// material point (its element's blocks r_A, r'_A, r_B, r'_B weighted by the Hermite shape
/// functions) or a point mass (its one block, weight 1).
struct PointLocation {
  int num_blocks = 0;
  std::array<Index, 4> dof{};      ///< first coordinate of each block
  std::array<double, 4> weight{};  ///< w_b
};

/// A point-to-point spring-damper (a compliant knot's link to a thread end, a tether, any
/// connection): force T(e, ė) along the line of its two points, e = |r₂ − r₁| − L₀
/// (forces/spring_damper.hpp).
struct SpringDamperLink {
  std::string name;
  ConnectionLaw law;
  double natural_length = 0.0;  ///< L₀ (m), ≥ 0; 0: a zero-length link with isotropic damping
  PointLocation first;
  PointLocation second;
  Index first_cable = -1;   ///< cable of the first point, or −1 for a point mass
  Index second_cable = -1;  ///< cable of the second point, or −1
  /// Tension T (N) at which the link fails and is removed (analysis/failure.hpp). Infinite:
  /// never.
  double breaking_force = std::numeric_limits<double>::infinity();
};

/// A rotational spring holding the cross-sections of two beam nodes together: the beam threads
/// meeting at a knot, so that the knot carries torsion and bending from one to the other
/// (forces/section_lock.hpp, W = (k/4) |R₁ − R₂|²_F).
struct SectionLock {
  std::string name;
  Index first_node = 0;   ///< a beam node (CableNode::section_dof ≥ 0)
  Index second_node = 0;  ///< another beam node
  /// Reference section frames [d₁ d₂ d₃] (d₁ = d₂ × d₃) of the nodes, from the initial r_y, r_z:
  /// the lock holds the sections' relative orientation of the start.
  Matrix3d first_frame = Matrix3d::Identity();
  Matrix3d second_frame = Matrix3d::Identity();
  double stiffness = 0.0;  ///< k (N m/rad), > 0
};

/// A cable point or point mass tied to a body point s_B by an isotropic linear spring-damper
/// (forces/body_attachment.hpp): f = −k (p − (x + R s_B)) − c (ṗ − (ẋ + R (ω × s_B))) on the
/// point, −f on the body at x + R s_B.
struct BodyAttachment {
  std::string name;
  PointLocation point;
  Index body = 0;
  Vector3d body_point = Vector3d::Zero();  ///< s_B (m, body frame)
  double stiffness = 0.0;                  ///< k (N/m), > 0
  double damping = 0.0;                    ///< c (N s/m), ≥ 0
};

/// A net as built by AddNet (model/net_builder.hpp): which point masses are its knots and which
/// cables its threads, for net metrics and outputs.
struct Net {
  std::string name;
  std::vector<Index> knots;           ///< point masses, in the order of the net's topology
  std::vector<Index> threads;         ///< cables
  std::vector<Index> perimeter;       ///< point masses around the mouth, in order
  std::vector<Index> corners;         ///< point masses
  Vector3d axis = Vector3d::UnitZ();  ///< launch axis: the normal of the net's plane
};

/// Force fixed in space (N) at a material point; scaled by the load factor in static analyses.
struct PointForce {
  MaterialPoint point;
  Vector3d force = Vector3d::Zero();
};

/// Moment (N m) at a cable node, acting on the slope coordinates r' through
/// Q_r' = (M × r') / |r'|² (docs/theory.md, "Point moment"). The cable carries no torsion, so the
/// component of M along the cable does no work. At a beam node it acts on r_x, r_y and r_z, each
/// with half that force, so that a rigid rotation δθ of an orthonormal frame does the work M·δθ,
/// torsion included (docs/theory.md, "Point moment on a beam node").
struct PointMoment {
  Index node = 0;
  Vector3d moment = Vector3d::Zero();
};

/// Force per unit reference length (N/m) on a whole cable, fixed in space.
struct DistributedLoad {
  Index cable = 0;
  Vector3d force_per_length = Vector3d::Zero();
};

/// The system description. Coordinates are numbered in the order things are added: six per
/// cable node (r, r'; three when the position is a knot's; six more, r_y and r_z, at a beam node),
/// three per point mass, six per rigid
/// body (x, ψ). A coordinate is either free (an unknown) or fixed at its initial value.
class Model {
 public:
  Index num_dofs() const { return num_dofs_; }
  Index num_nodes() const { return static_cast<Index>(nodes_.size()); }
  const std::vector<Cable>& cables() const { return cables_; }
  const std::vector<CableNode>& nodes() const { return nodes_; }
  const std::vector<PointMass>& point_masses() const { return point_masses_; }
  const std::vector<SpringDamperLink>& links() const { return links_; }
  /// Section locks between beam nodes (knots of beam threads).
  const std::vector<SectionLock>& section_locks() const { return section_locks_; }
  const std::vector<Net>& nets() const { return nets_; }
  /// Rigid bodies (model/rigid_body.hpp) and their attachments.
  const std::vector<RigidBody>& rigid_bodies() const { return rigid_bodies_; }
  const std::vector<BodyAttachment>& body_attachments() const { return body_attachments_; }
  /// Revolute and spherical clearance joints (model/clearance_joint.hpp).
  const std::vector<ClearanceJoint>& clearance_joints() const { return clearance_joints_; }
  /// Ideal joints: constraints with Lagrange multipliers (model/ideal_joint.hpp).
  const std::vector<IdealJoint>& ideal_joints() const { return ideal_joints_; }
  /// Number of constraint equations of the ideal joints (Lagrange multipliers).
  Index num_constraint_equations() const;
  /// True when a rigid body moves freely (static and modal analyses refuse such models).
  bool has_free_bodies() const;
  const std::vector<CableElement>& elements() const { return elements_; }
  /// The beam elements; each has its centre line in elements().
  const std::vector<BeamElement>& beam_elements() const { return beam_elements_; }
  const std::vector<PointForce>& point_forces() const { return point_forces_; }
  const std::vector<PointMoment>& point_moments() const { return point_moments_; }
  const std::vector<DistributedLoad>& distributed_loads() const { return distributed_loads_; }
  const Vector3d& gravity() const { return gravity_; }
  /// Mean motion n (rad/s) of the target's circular orbit when the model is written in its
  /// Hill frame (forces/orbital_frame.hpp); empty for an inertial frame.
  const std::optional<double>& orbital_frame() const { return orbital_frame_; }
  /// Rayleigh and modal damping of the whole model (solvers/damping_model.hpp).
  const DampingSpec& damping() const { return damping_; }
  /// Contact with rigid targets (forces/target_contact.hpp).
  const ContactSpec& contact() const { return contact_; }
  /// Fixed coordinates that move: chasers, hubs (model/prescribed_motion.hpp).
  const std::vector<PrescribedBlock>& prescribed() const { return prescribed_; }
  /// Per coordinate: true when fixed (eliminated from the unknowns).
  const std::vector<bool>& fixed() const { return fixed_; }
  const VectorXd& initial_positions() const { return initial_positions_; }
  const VectorXd& initial_velocities() const { return initial_velocities_; }
  /// Total mass of the cables, point masses and rigid bodies (kg).
  double total_mass() const;

  /// Nodal coordinates of a beam element gathered from a global vector.
  Vector24d Gather(const BeamElement& element, const VectorXd& x) const;
  /// First global coordinate of a node's position r and of its slope r'.
  Index NodePositionDof(Index node) const { return nodes_[node].position_dof; }
  Index NodeSlopeDof(Index node) const { return nodes_[node].slope_dof; }
  /// Index of the cable with this name; throws InputError (listing the names) when there is none.
  Index FindCable(const std::string& name) const;
  /// Index of the point mass with this name, or −1.
  Index FindPointMass(const std::string& name) const;
  /// Index of the rigid body with this name, or −1.
  Index FindRigidBody(const std::string& name) const;
  /// Material point at fraction s ∈ [0, 1] of a cable's reference length.
  MaterialPoint LocateCablePoint(Index cable, double s) const;
  /// Node at fraction s of a cable; throws InputError when s is not at a node.
  Index LocateCableNode(Index cable, double s) const;
  /// Nodal coordinates of an element gathered from a global vector.
  Vector12d Gather(const CableElement& element, const VectorXd& x) const;
  /// Position (or, given velocities, velocity) of a material point.
  Vector3d Interpolate(const MaterialPoint& point, const VectorXd& x) const;
  /// Position (or velocity) of a located point: Σ_b w_b x_b.
  static Vector3d Locate(const PointLocation& point, const VectorXd& x);
  /// The blocks and weights of a cable material point.
  PointLocation LocateMaterialPoint(const MaterialPoint& point) const;
  /// The point mass named `name`, or else the point at fraction s of the cable named `name`;
  /// throws InputError when neither exists.
  PointLocation LocatePoint(const std::string& name, double s) const;

 private:
  friend class ModelBuilder;
  // Cables, point masses and rigid bodies by name (one name space, ModelBuilder::CheckNameIsFree),
  // so that finding one costs O(1) however large the net.
  enum class NamedKind { kCable, kPointMass, kRigidBody };
  std::unordered_map<std::string, std::pair<NamedKind, Index>> names_;
  // The index of `name` if it names a thing of `kind`, else −1.
  Index FindNamed(const std::string& name, NamedKind kind) const;
  std::vector<Cable> cables_;
  std::vector<CableNode> nodes_;
  std::vector<CableElement> elements_;
  std::vector<BeamElement> beam_elements_;
  std::vector<PointMass> point_masses_;
  std::vector<SpringDamperLink> links_;
  std::vector<SectionLock> section_locks_;
  std::vector<Net> nets_;
  std::vector<RigidBody> rigid_bodies_;
  std::vector<BodyAttachment> body_attachments_;
  std::vector<ClearanceJoint> clearance_joints_;
  std::vector<IdealJoint> ideal_joints_;
  std::vector<PointForce> point_forces_;
  std::vector<PointMoment> point_moments_;
  std::vector<DistributedLoad> distributed_loads_;
  Vector3d gravity_ = Vector3d::Zero();
  std::optional<double> orbital_frame_;
  DampingSpec damping_;
  ContactSpec contact_;
  std::vector<bool> fixed_;
  std::vector<PrescribedBlock> prescribed_;
  // While the model is built, the two vectors below hold spare capacity beyond num_dofs_, so that
  // adding coordinates node by node costs linear time in all (ModelBuilder::AddCoordinates);
  // ModelBuilder::Build trims them to num_dofs_.
  Index num_dofs_ = 0;
  VectorXd initial_positions_;
  VectorXd initial_velocities_;
};

}  // namespace ancfnet
