#pragma once
/// @file Probes: named quantities recorded at every output step.

#include <string>
#include <vector>

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

enum class ProbeQuantity {
  kPosition,          ///< NAME.x/y/z of a point
  kVelocity,          ///< NAME.vx/vy/vz of a point
  kEnergy,            ///< NAME.kinetic/strain/gravity/work/dissipated of the whole system
  kMouthArea,         ///< NAME.area: the net's perimeter polygon projected normal to its axis (m²)
  kCentroid,          ///< NAME.x/y/z: mean position of the net's knots (m)
  kCentroidVelocity,  ///< NAME.vx/vy/vz: mean velocity of the net's knots (m/s)
  kDistance,          ///< NAME.distance: travel of that centroid along the net's axis (m)
  kMaxTension,  ///< NAME.tension, NAME.thread: largest thread tension of a net (N) and its thread
  kLinkForce,   ///< NAME.tension, NAME.fx/fy/fz: a link's tension T (N) and force on its 2nd point
  /// NAME.x/y/z, NAME.qw/qx/qy/qz: a rigid body's position x_WB (m) and orientation R_WB as a unit
  /// quaternion (qw ≥ 0)
  kBodyPose,
  /// NAME.vx/vy/vz, NAME.wx/wy/wz: a rigid body's velocity ẋ_WB (m/s, world) and angular
  /// velocity ω_B (rad/s, body frame)
  kBodyVelocity,
  /// NAME.active, NAME.normal_force, NAME.friction_force, NAME.fx/fy/fz, NAME.mx/my/mz,
  /// NAME.max_penetration: the active contacts (of one target, or all), see ContactProbeValues.
  kContact,
  /// NAME.ex/ey/ez, NAME.penetration, NAME.normal_force, NAME.friction_force,
  /// NAME.friction_moment, NAME.mode of a clearance joint (forces/clearance_joint_forces.hpp):
  /// the eccentricity e of the journal relative to the bearing (m, world axes; in the joint's
  /// plane for a revolute joint: its orbit), δ = |e| − c (m, < 0 in free flight), F_n (N), |f_t|
  /// (N), the friction moment on the journal m_J (N m; its component along the axis for a
  /// revolute joint, its magnitude for a spherical one) and the mode (0 free flight, 1 contact,
  /// 2 impact).
  kClearanceJoint,
  /// NAME.fx/fy/fz, NAME.mx/my/mz: the force (N) an ideal joint applies to its second side and
  /// its moment about that side's centre (N m), world axes (forces/joint_constraints.hpp).
  kJointReaction,
  /// NAME.contact, NAME.enclosed, NAME.mouth_ratio, NAME.knot_coverage, NAME.thread_coverage,
  /// NAME.thread_tension, NAME.thread_load, NAME.tether_tension, NAME.tether_load,
  /// NAME.escaped: the capture metrics of net `net` round target `target`
  /// (analysis/capture_metrics.hpp): contact (0/1), Q, A/A₀, the fractions of knots and threads
  /// touching, the largest thread and tether tensions (N) and their ratios to the breaking
  /// force (CalcLoadRatio), escaped (0/1).
  kCapture,
};

/// A named probe. Position and velocity probes read a point (a cable material point or a point
/// mass); energy probes read the whole system; net probes read net `net`; link probes link `link`
/// (0 once it has failed); body probes body `body`; contact probes the contacts with target
/// `target` (−1: all contacts).
struct Probe {
  std::string name;
  ProbeQuantity quantity = ProbeQuantity::kPosition;
  PointLocation point;
  Index net = -1;
  Index link = -1;
  Index body = -1;
  /// kContact: index into ContactSpec::targets, or −1 for every contact; kCapture: the target
  Index target = -1;
  /// kClearanceJoint: index into Model::clearance_joints(); kJointReaction: into
  /// Model::ideal_joints().
  Index joint = -1;
  Vector3d reference = Vector3d::Zero();  ///< kDistance: the centroid at the start
  double reference_area = 0.0;            ///< kCapture: the net's mouth area at the start (m²)
};

/// The largest elastic tension over a net's threads (N, CalcCableMaxTension of
/// analysis/cable_tension.hpp: at the ends and midpoints of their elements) and the index of its
/// thread in the net (cable net.threads[thread], named NAME.t<thread>).
struct ThreadTension {
  double tension = 0.0;
  Index thread = -1;
};
ThreadTension CalcMaxThreadTension(const Model& model, const Net& net, const VectorXd& q);

/// Mean position of a net's knots (m).
Vector3d CalcNetCentroid(const Model& model, const Net& net, const VectorXd& q);

/// The net's mouth area (m², CalcMouthArea of its perimeter knots projected normal to its axis)
/// at coordinates q.
double CalcNetMouthArea(const Model& model, const Net& net, const VectorXd& q);

/// What a contact probe reports of a set of active contacts (ContactPoint records): their number,
/// Σ F_n (N), Σ |f_t| (N, the sum of the friction forces' magnitudes), the force the targets feel,
/// F = −Σ f (N, f = force_W on the probe, self-contacts left out), its moment about `reference`,
/// M = Σ (p − reference) × (−f) (N m, p = point_W on the target's surface), and the largest
/// penetration max δ (m; 0 without contact).
struct ContactProbeValues {
  int active = 0;
  double normal_force = 0.0;
  double friction_force = 0.0;
  Vector3d force_on_target = Vector3d::Zero();
  Vector3d moment_on_target = Vector3d::Zero();
  double max_penetration = 0.0;
};

/// ContactProbeValues of the records with `target` (−1: every record; the target force and moment
/// then add up the forces on all targets, about `reference`).
ContactProbeValues CalcContactProbeValues(const std::vector<ContactPoint>& contacts, Index target,
                                          const Vector3d& reference);

/// Column names of a probe: NAME.x/y/z, NAME.vx/vy/vz, or NAME.kinetic, NAME.strain,
/// NAME.gravity, NAME.work, NAME.dissipated.
std::vector<std::string> ProbeColumns(const Probe& probe);

/// Values of a probe in the order of ProbeColumns, appended to `values`. `contacts` are the active
/// contacts at `state` (TargetContact::CollectContacts), read by contact probes only. A contact
/// probe of one target takes moments about that target's `point`, of all targets about the origin.
void EvaluateProbe(const Probe& probe, const Model& model, const State& state,
                   const EnergyAccount& energy, const std::vector<ContactPoint>& contacts,
                   std::vector<double>* values);

}  // namespace ancfnet
