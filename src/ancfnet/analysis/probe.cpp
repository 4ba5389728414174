#include "ancfnet/analysis/probe.hpp"

#include <algorithm>
#include <limits>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/analysis/capture_metrics.hpp"
#include "ancfnet/analysis/net_metrics.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/forces/joint_constraints.hpp"
#include "ancfnet/forces/link_forces.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {

std::vector<std::string> ProbeColumns(const Probe& probe) {
  const std::string& n = probe.name;
  switch (probe.quantity) {
    case ProbeQuantity::kPosition:
      return {n + ".x", n + ".y", n + ".z"};
    case ProbeQuantity::kVelocity:
      return {n + ".vx", n + ".vy", n + ".vz"};
    case ProbeQuantity::kEnergy:
      return {n + ".kinetic", n + ".strain", n + ".gravity", n + ".work", n + ".dissipated"};
    case ProbeQuantity::kMouthArea:
      return {n + ".area"};
    case ProbeQuantity::kCentroid:
      return {n + ".x", n + ".y", n + ".z"};
    case ProbeQuantity::kCentroidVelocity:
      return {n + ".vx", n + ".vy", n + ".vz"};
    case ProbeQuantity::kDistance:
      return {n + ".distance"};
    case ProbeQuantity::kMaxTension:
      return {n + ".tension", n + ".thread"};
    case ProbeQuantity::kLinkForce:
      return {n + ".tension", n + ".fx", n + ".fy", n + ".fz"};
    case ProbeQuantity::kBodyPose:
      return {n + ".x", n + ".y", n + ".z", n + ".qw", n + ".qx", n + ".qy", n + ".qz"};
    case ProbeQuantity::kBodyVelocity:
      return {n + ".vx", n + ".vy", n + ".vz", n + ".wx", n + ".wy", n + ".wz"};
    case ProbeQuantity::kContact:
      return {n + ".active",
              n + ".normal_force",
              n + ".friction_force",
              n + ".fx",
              n + ".fy",
              n + ".fz",
              n + ".mx",
              n + ".my",
              n + ".mz",
              n + ".max_penetration"};
    case ProbeQuantity::kClearanceJoint:
      return {n + ".ex",
              n + ".ey",
              n + ".ez",
              n + ".penetration",
              n + ".normal_force",
              n + ".friction_force",
              n + ".friction_moment",
              n + ".mode"};
    case ProbeQuantity::kJointReaction:
      return {n + ".fx", n + ".fy", n + ".fz", n + ".mx", n + ".my", n + ".mz"};
    case ProbeQuantity::kCapture:
      return {n + ".contact",       n + ".enclosed",        n + ".mouth_ratio",
              n + ".knot_coverage", n + ".thread_coverage", n + ".thread_tension",
              n + ".thread_load",   n + ".tether_tension",  n + ".tether_load",
              n + ".escaped"};
  }
  return {};
}

ThreadTension CalcMaxThreadTension(const Model& model, const Net& net, const VectorXd& q) {
  ThreadTension result{.tension = -std::numeric_limits<double>::infinity(), .thread = -1};
  for (std::size_t j = 0; j < net.threads.size(); ++j) {
    const double t = CalcCableMaxTension(model, model.cables()[net.threads[j]], q);
    if (t > result.tension) result = {.tension = t, .thread = static_cast<Index>(j)};
  }
  return result;
}

Vector3d CalcNetCentroid(const Model& model, const Net& net, const VectorXd& q) {
  // (Given velocities, the mean velocity of the knots.)
  std::vector<Vector3d> knots;
  for (Index knot : net.knots) knots.push_back(q.segment<3>(model.point_masses()[knot].dof));
  return CalcCentroid(knots);
}

double CalcNetMouthArea(const Model& model, const Net& net, const VectorXd& q) {
  std::vector<Vector3d> polygon;
  for (Index knot : net.perimeter) polygon.push_back(q.segment<3>(model.point_masses()[knot].dof));
  return CalcMouthArea(polygon, net.axis);
}

ContactProbeValues CalcContactProbeValues(const std::vector<ContactPoint>& contacts, Index target,
                                          const Vector3d& reference) {
  ContactProbeValues r;
  for (const ContactPoint& c : contacts) {
    if (target >= 0 && c.target != target) continue;
    ++r.active;
    r.normal_force += c.normal_force;
    r.friction_force += c.friction_force_W.norm();
    r.max_penetration = std::max(r.max_penetration, c.penetration);
    if (c.target < 0) continue;  // a self-contact: no force on a target
    r.force_on_target -= c.force_W;
    r.moment_on_target -= (c.point_W - reference).cross(c.force_W);
  }
  return r;
}

void EvaluateProbe(const Probe& probe, const Model& model, const State& state,
                   const EnergyAccount& energy, const std::vector<ContactPoint>& contacts,
                   std::vector<double>* values) {
  switch (probe.quantity) {
    case ProbeQuantity::kPosition:
    case ProbeQuantity::kVelocity: {
      const VectorXd& x = probe.quantity == ProbeQuantity::kPosition ? state.q : state.v;
      const Vector3d p = Model::Locate(probe.point, x);
      values->insert(values->end(), {p.x(), p.y(), p.z()});
      break;
    }
    case ProbeQuantity::kEnergy:
      values->insert(values->end(), {energy.kinetic, energy.strain, energy.gravity, energy.work,
                                     energy.dissipated});
      break;
    case ProbeQuantity::kMouthArea:
      values->push_back(CalcNetMouthArea(model, model.nets()[probe.net], state.q));
      break;
    case ProbeQuantity::kCentroid:
    case ProbeQuantity::kCentroidVelocity: {
      // The centroid is linear in the knot positions: its velocity is the same mean of velocities.
      const VectorXd& x = probe.quantity == ProbeQuantity::kCentroid ? state.q : state.v;
      const Vector3d c = CalcNetCentroid(model, model.nets()[probe.net], x);
      values->insert(values->end(), {c.x(), c.y(), c.z()});
      break;
    }
    case ProbeQuantity::kDistance: {
      const Net& net = model.nets()[probe.net];
      values->push_back(
          CalcDistanceTravelled(probe.reference, CalcNetCentroid(model, net, state.q), net.axis));
      break;
    }
    case ProbeQuantity::kMaxTension: {
      const ThreadTension t = CalcMaxThreadTension(model, model.nets()[probe.net], state.q);
      values->insert(values->end(), {t.tension, static_cast<double>(t.thread)});
      break;
    }
    case ProbeQuantity::kLinkForce: {
      if (state.link_broken[probe.link]) {
        values->insert(values->end(), {0.0, 0.0, 0.0, 0.0});
        break;
      }
      const SpringDamperResult r = CalcLinkState(model.links()[probe.link], state.q, state.v);
      values->insert(values->end(),
                     {r.tension, r.force_on_2.x(), r.force_on_2.y(), r.force_on_2.z()});
      break;
    }
    case ProbeQuantity::kBodyPose: {
      const BodyPose pose = CalcBodyPose(model, state, probe.body);
      Eigen::Quaterniond quaternion(pose.R_WB);
      if (quaternion.w() < 0.0) quaternion.coeffs() *= -1.0;
      values->insert(values->end(), {pose.p_WB.x(), pose.p_WB.y(), pose.p_WB.z(), quaternion.w(),
                                     quaternion.x(), quaternion.y(), quaternion.z()});
      break;
    }
    case ProbeQuantity::kBodyVelocity: {
      const BodyVelocity v = CalcBodyVelocity(model.rigid_bodies()[probe.body], state.v);
      values->insert(values->end(),
                     {v.v_WB.x(), v.v_WB.y(), v.v_WB.z(), v.w_B.x(), v.w_B.y(), v.w_B.z()});
      break;
    }
    case ProbeQuantity::kContact: {
      // The moment is taken about the target's reference point, or its body's origin.
      Vector3d reference = Vector3d::Zero();
      if (probe.target >= 0) {
        const ContactTarget& target = model.contact().targets[probe.target];
        reference = target.body >= 0 ? CalcBodyPose(model, state, target.body).p_WB : target.point;
      }
      const ContactProbeValues c = CalcContactProbeValues(contacts, probe.target, reference);
      const Vector3d& f = c.force_on_target;
      const Vector3d& m = c.moment_on_target;
      values->insert(values->end(),
                     {static_cast<double>(c.active), c.normal_force, c.friction_force, f.x(), f.y(),
                      f.z(), m.x(), m.y(), m.z(), c.max_penetration});
      break;
    }
    case ProbeQuantity::kClearanceJoint: {
      const ClearanceJoint& joint = model.clearance_joints()[probe.joint];
      const ClearanceJointState s =
          CalcClearanceJointState(model, probe.joint, state.q, state.v, state.body_rotation,
                                  state.joint_history[probe.joint]);
      const ClearanceContact& c = s.contact;
      const double moment = joint.type == ClearanceJoint::Type::kRevolute
                                ? c.journal_moment.dot(joint.axis)
                                : c.journal_moment.norm();
      values->insert(values->end(),
                     {c.eccentricity.x(), c.eccentricity.y(), c.eccentricity.z(), c.penetration,
                      c.normal_force, c.friction.norm(), moment, static_cast<double>(s.mode)});
      break;
    }
    case ProbeQuantity::kJointReaction: {
      JointConstraints constraints(model);
      constraints.Evaluate(state.q, state.v, state.body_rotation);
      const JointReaction r = constraints.CalcReaction(probe.joint, state.multipliers);
      values->insert(values->end(), {r.force.x(), r.force.y(), r.force.z(), r.moment.x(),
                                     r.moment.y(), r.moment.z()});
      break;
    }
    case ProbeQuantity::kCapture: {
      const CaptureMetrics m =
          CalcCaptureMetrics(model, state, probe.net, probe.target, contacts, probe.reference_area);
      values->insert(
          values->end(),
          {m.in_contact ? 1.0 : 0.0, m.enclosed_fraction, m.mouth_area_ratio, m.knot_coverage,
           m.thread_coverage, m.thread_tension,
           CalcLoadRatio(m.thread_tension, m.thread_breaking_force), m.tether_tension,
           CalcLoadRatio(m.tether_tension, m.tether_breaking_force), m.escaped ? 1.0 : 0.0});
      break;
    }
  }
}

}  // namespace ancfnet
