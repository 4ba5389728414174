#pragma once
/// @file ModelBuilder: the public C++ API that assembles a Model. The YAML loader and (later) the
/// Python bindings go through it, so every check on the input lives here once.

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ancfnet/model/beam_section.hpp"
#include "ancfnet/model/clearance_joint_spec.hpp"
#include "ancfnet/model/ideal_joint_spec.hpp"
#include "ancfnet/model/model.hpp"

namespace ancfnet {

/// What makes a cable a beam of ANCF beam elements (elements/ancf_beam.hpp): its material, its
/// section in the principal axes (y along d₂, z along d₃) and the direction of d₂ at the start,
/// `orientation`, from which the reference directors are made by Gram–Schmidt against the axis
/// (MakeBeamSectionFrame: d₂ ⊥ axis, d₃ = t × d₂).
struct BeamCableSpec {
  BeamMaterial material;
  BeamSection section;
  Vector3d orientation = Vector3d::Zero();  ///< non-zero, not parallel to end − start
};

/// A straight cable from `start` to `end` divided into equal elements. Its natural (stress-free)
/// length defaults to |end − start|; a longer one starts slack (compressed, |r'| < 1), a shorter
/// one pre-tensioned. An end may share its position coordinates with a point mass (an ideal
/// knot): the cable's start (end) is then that mass's position, and `start` (`end`) must equal it.
struct CableSpec {
  std::string name;
  Vector3d start = Vector3d::Zero();  ///< m
  Vector3d end = Vector3d::Zero();    ///< m
  int num_elements = 1;               ///< ≥ 1
  CableProperties properties;
  double natural_length = 0.0;  ///< m; 0: |end − start|
  std::string start_knot = {};  ///< point mass whose position the start shares ("" : none)
  std::string end_knot = {};    ///< point mass whose position the end shares ("" : none)
  /// Tension (N) at which the cable fails and the links holding it break; > 0, infinite: never.
  /// A cable that can fail cannot share knots' positions at both ends (it would stay attached);
  /// it comes off where a link holds it.
  double breaking_force = std::numeric_limits<double>::infinity();
  /// Set: the cable is made of beam elements, and `properties` keep only the drawing radius
  /// (EA, EI and ρA of its centre line come from the beam; damping times and the rope law must
  /// stay unset, the beam element has neither).
  std::optional<BeamCableSpec> beam = std::nullopt;
  /// An earlier cable whose end node this cable's start shares, position and slope (and the
  /// section gradients when both are beams): a mixed mesh, cable elements then beam elements in
  /// one line. This cable must be its straight continuation: `start` at its end, the same
  /// direction and stretch (and, for two beams, the same section frame). Excludes start_knot.
  std::string start_cable = {};
};

/// A point of a named cable at fraction s ∈ [0, 1] of its reference length.
/// (Where a point mass is accepted, `cable` may also name a point mass; s is then ignored.)
struct CablePointRef {
  std::string cable;
  double s = 0.0;
};

/// A cable point or point mass tied to a point of a rigid body (forces/body_attachment.hpp).
struct BodyAttachmentSpec {
  std::string name;
  std::string body;
  /// A point mass (by name, s ignored) or a cable point.
  CablePointRef point;
  /// s_B (m, body frame); default: where the point is at t = 0, R_WBᵀ (p₀ − x_WB).
  std::optional<Vector3d> body_point = std::nullopt;
  /// k (N/m, > 0); default: the stiff penalty of a fixed attachment,
  /// CalcFixedAttachmentStiffness from the masses and `time_step`.
  std::optional<double> stiffness = std::nullopt;
  /// c (N s/m, ≥ 0); default: 2 √(k m_eff) (critical for the pair) with the default stiffness,
  /// else 0.
  std::optional<double> damping = std::nullopt;
  double time_step = 0.0;  ///< h (s) for the default stiffness; > 0 when `stiffness` is absent
};

/// Which coordinates of a cable node to fix: x, y, z of r, then of r'.
using CoordinateMask = std::array<bool, kCableNodeDofs>;

/// Builds a Model step by step. Every method validates its arguments and throws InputError with
/// a one-line message naming the offending value (callers add the file and line).
class ModelBuilder {
 public:
  /// Gravitational acceleration (m/s²) acting on every cable.
  void SetGravity(const Vector3d& gravity);
  /// Writes the model in the Hill frame of a target on a circular orbit of mean motion n > 0
  /// (rad/s): Clohessy–Wiltshire relative dynamics (forces/orbital_frame.hpp).
  void SetOrbitalFrame(double mean_motion);
  /// Rayleigh damping C = α M + β K₀ of the whole model (α, β ≥ 0; see FitRayleighDamping).
  void SetRayleighDamping(const RayleighDamping& damping);
  /// Modal damping of the lowest elastic modes (num_modes ≥ 1; ratios in [0, 1), one per mode,
  /// or a table of ≥ 1 (frequency > 0 Hz, ratio) pairs with increasing frequencies).
  void SetModalDamping(const ModalDamping& damping);
  /// Contact of every cable and point mass with rigid targets (unit normals and axes, positive
  /// radii and extents, a valid law). Replaces an earlier setting.
  void SetContact(const ContactSpec& contact);
  /// Adds a cable; returns its index. Names must be unique and non-empty.
  Index AddCable(const CableSpec& spec);
  /// Adds a point mass m ≥ 0 (kg) at `position` (m) moving at `velocity` (m/s); returns its
  /// index. Names are unique among point masses and cables. A massless point (an ideal knot
  /// without a knot mass) must have cables attached, or the mass matrix is singular.
  Index AddPointMass(const std::string& name, double mass, const Vector3d& position,
                     const Vector3d& velocity = Vector3d::Zero());
  /// Sets the initial velocity (m/s) of a point mass.
  void SetPointMassVelocity(const std::string& name, const Vector3d& velocity);
  /// Fixes the position of a point mass.
  void FixPointMass(const std::string& name);
  /// Moves a point mass at a constant velocity (m/s): its position is prescribed,
  /// r(t) = r₀ + v t (a chaser, a moving anchor). The work its reaction does is not in the energy
  /// account's W.
  void MovePointMass(const std::string& name, const Vector3d& velocity);
  /// Adds a spring-damper between two points, each a point mass (named by `cable`, s ignored) or
  /// a cable point. Its natural length defaults to the initial distance of the points. It fails
  /// (is removed) once its tension reaches `breaking_force` (N, > 0; infinite: never).
  void AddSpringDamper(const std::string& name, const CablePointRef& first,
                       const CablePointRef& second, const ConnectionLaw& law,
                       std::optional<double> natural_length = std::nullopt,
                       double breaking_force = std::numeric_limits<double>::infinity());
  /// Adds a section lock (model.hpp, SectionLock) between the beam nodes at `first` and `second`
  /// (nodes of beam cables, different), holding their sections' relative orientation of now.
  /// Its stiffness k (N m/rad, > 0) defaults to kSectionLockStiffnessFactor · max(GJ, EI_y,
  /// EI_z)/L_e over the beam elements next to the two nodes: the lock then turns by less than
  /// 1/kSectionLockStiffnessFactor of what one such element twists or bends under the same moment.
  void AddSectionLock(const std::string& name, const CablePointRef& first,
                      const CablePointRef& second, std::optional<double> stiffness = std::nullopt);
  static constexpr double kSectionLockStiffnessFactor = 100.0;
  /// Adds a rigid body (model/rigid_body.hpp) with six coordinates (x_WB, ψ); returns its index.
  /// Its name is unique among cables, point masses and bodies; mass > 0; inertia SPD with
  /// principal moments satisfying the triangle inequality; orientation a rotation matrix. A
  /// prescribed body moves as x(t) = x₀ + v t, R(t) = R₀ exp(t ω̃_B) (its coordinates are
  /// eliminated and ψ = t ω_B). Gravity acts on free bodies. Bodies exclude an orbital frame (not
  /// yet), free bodies modal damping (Build throws); Rayleigh damping acts on the cables only.
  Index AddRigidBody(const RigidBodySpec& spec);
  /// Ties a point to a body point (BodyAttachmentSpec).
  void AddBodyAttachment(const BodyAttachmentSpec& spec);
  /// Adds a revolute or spherical clearance joint (model/clearance_joint_spec.hpp): a unique
  /// name, 0 < c < R_J, a non-zero axis, a valid law and a regularised friction law, anchors that
  /// name existing bodies, point masses or cable points, not both the ground. Bodies first.
  void AddClearanceJoint(const ClearanceJointSpec& spec);
  /// Adds an ideal joint (model/ideal_joint_spec.hpp): a name unique among all joints, sides
  /// that name existing bodies, point masses or cable points, not both the ground; revolute and
  /// prismatic: each side the ground or a body (a revolute's first side may be a cable point, its
  /// axis along the cable's tangent); weld: the first a cable point, the second the ground or a
  /// body; a non-zero axis; the two sides' points within 1e-9 m (relative to the model's size)
  /// of each other at t = 0. Bodies first.
  void AddIdealJoint(const IdealJointSpec& spec);
  /// Fixes position and slope of the node at `at` (which must be a node). At a beam node it fixes
  /// the position and the section directors d₂ = r_y, d₃ = r_z and leaves the slope r_x free,
  /// so that the centre line may leave the clamp sheared as in Timoshenko's theory (w = 0, θ = 0,
  /// w' = γ); the slope is fixed too when a cable element shares the node.
  void AddClamp(const CablePointRef& at);
  /// Fixes the position of the node at `at`; the slope stays free.
  void AddPin(const CablePointRef& at);
  /// Clamps the node at `at` to a hub turning by θ(t) about the axis through `center` along
  /// `axis` (normalised; non-zero): its position and slope are prescribed,
  /// r(t) = c + R(θ) (r₀ − c), r'(t) = R(θ) r'₀; at a beam node the coordinates AddClamp fixes
  /// there turn as directions (model/prescribed_motion.hpp).
  void AddRotatingClamp(const CablePointRef& at, const Vector3d& axis, const Vector3d& center,
                        const AngleProfile& angle);
  /// Fixes the chosen coordinates of the node at `at`.
  void FixCoordinates(const CablePointRef& at, const CoordinateMask& mask);
  /// Force fixed in space (N) at any material point.
  void AddPointForce(const CablePointRef& at, const Vector3d& force);
  /// Moment (N m) at a node (a cable end, typically).
  void AddPointMoment(const CablePointRef& at, const Vector3d& moment);
  /// Load per unit length (N/m) on a whole cable.
  void AddDistributedLoad(const std::string& cable, const Vector3d& force_per_length);
  /// Initial velocity of every point of a cable: v (m/s) plus ω × (r − center), ω in rad/s.
  void SetInitialVelocity(const std::string& cable, const Vector3d& velocity,
                          const Vector3d& angular_velocity = Vector3d::Zero(),
                          const Vector3d& center = Vector3d::Zero());
  /// Records a net's description (its knots, threads, perimeter); AddNet calls it.
  void AddNetDescription(const Net& net);
  /// The finished model. Throws InputError when it has no cable, or when rigid bodies meet what
  /// they do not support yet (an orbital frame, modal damping of free bodies).
  Model Build() const;

 private:
  Index LocateNode(const CablePointRef& at) const;
  // First coordinates of the 3-blocks a clamp fixes at a node (AddClamp).
  std::vector<Index> ClampedBlocks(Index node) const;
  void CheckNameIsFree(const std::string& name) const;
  // Throws InputError when a clearance or ideal joint is already named `name`.
  void CheckJointNameIsFree(const std::string& name) const;
  // The mass that moves with a located point: a point mass's, or half its cable element's.
  double PointMassOf(const CablePointRef& point) const;
  // Appends n coordinates with these initial values, free and at rest; returns the first.
  Index AddCoordinates(const VectorXd& initial_values);
  // Position coordinates of a cable end: the named knot's, or new ones at `position`.
  Index EndPositionDof(const std::string& knot, const Vector3d& position, const char* which);
  // The node a cable continuing `spec.start_cable` starts at (checked to be its continuation).
  CableNode ContinuedNode(const CableSpec& spec, const Vector3d& slope,
                          const BeamSectionFrame* frame) const;
  // Appends the beam elements of a beam cable whose centre-line elements are already added.
  void AddBeamElements(const CableSpec& spec, Index cable_index);
  Model model_;
};

}  // namespace ancfnet
