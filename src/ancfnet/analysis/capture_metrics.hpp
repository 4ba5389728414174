#pragma once
/// @file Capture metrics of a net round a target (docs/theory.md, "Capture metrics"): contact,
/// how much of the target the net encloses, how far its mouth has closed, how much of it touches
/// the target, how near its threads and tether are to breaking, and whether the target escapes.

#include <limits>
#include <vector>

#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// The capture metrics of one net and one contact target at one state.
struct CaptureMetrics {
  bool in_contact = false;  ///< some knot or thread of the net touches the target
  /// Capture quality Q ∈ [0, 1]: the fraction of the target's bounding ball inside the convex
  /// hull of the net's knots and thread nodes (ConvexHull::CalcBallFractionInside).
  double enclosed_fraction = 0.0;
  /// A / A₀: the mouth area (CalcNetMouthArea) over its initial value; 0 when A₀ = 0 (a net
  /// without a perimeter, or one that starts folded flat).
  double mouth_area_ratio = 0.0;
  double knot_coverage = 0.0;    ///< knots touching the target / knots
  double thread_coverage = 0.0;  ///< threads touching the target / threads
  double thread_tension = 0.0;   ///< largest thread tension T (N, CalcMaxThreadTension)
  /// Smallest breaking force of the net's threads (N); infinite: they never break.
  double thread_breaking_force = std::numeric_limits<double>::infinity();
  bool has_tether = false;      ///< the net has a tether, cable "NET.tether" (AddNetTether)
  double tether_tension = 0.0;  ///< its largest tension (N; 0 without a tether)
  double tether_breaking_force = std::numeric_limits<double>::infinity();  ///< N
  /// The target's centre is outside the net's hull and moves away from the net's centroid
  /// (IsTargetEscaping).
  bool escaped = false;
};

/// How much of a net touches a contact target: whether any of it does, and the fractions of its
/// knots and of its threads with a contact record with the target (self-contacts do not count).
struct ContactCoverage {
  bool in_contact = false;
  double knot_coverage = 0.0;    ///< knots touching the target / knots
  double thread_coverage = 0.0;  ///< threads touching the target / threads
};

/// The contact coverage of net `net` on contact target `target`, from the active contacts
/// `contacts` (TargetContact::CollectContacts); each knot and thread counts once.
ContactCoverage CalcContactCoverage(const Model& model, const Net& net, Index target,
                                    const std::vector<ContactPoint>& contacts);

/// Safety factor S = T_break / T_max against breaking (Botta, Sharf & Misra 2017 compare the
/// peak tether tension with the breaking strength): infinite when T_max ≤ 0 or T_break is
/// infinite.
double CalcSafetyFactor(double breaking_force, double max_tension);

/// Load ratio T_max / T_break = 1/S, finite for probes.csv: 0 when T_break is infinite, and
/// never negative (a slack or compressed line has ratio 0).
double CalcLoadRatio(double max_tension, double breaking_force);

/// Escape test (ours): the target's centre p_T (m) is not inside the net's hull, and it moves
/// away from the net's centroid p_N, (v_T − v_N)·(p_T − p_N) > 0, with v_T and v_N their
/// velocities (m/s).
bool IsTargetEscaping(bool centre_inside_hull, const Vector3d& p_T, const Vector3d& v_T,
                      const Vector3d& p_N, const Vector3d& v_N);

/// The capture metrics of net `net` round contact target `target` (a bounded one: not a plane)
/// at `state`, whose active contacts are `contacts` (TargetContact::CollectContacts), with the
/// net's initial mouth area `initial_mouth_area` (m², ≥ 0). The target's bounding ball
/// (CalcTargetBoundingSphere) moves with its body; the ball is sampled on 16 cells per axis.
CaptureMetrics CalcCaptureMetrics(const Model& model, const State& state, Index net, Index target,
                                  const std::vector<ContactPoint>& contacts,
                                  double initial_mouth_area);

}  // namespace ancfnet
