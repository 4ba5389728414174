#include "ancfnet/analysis/capture_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/analysis/convex_hull.hpp"
#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/contact/target_distance.hpp"
#include "ancfnet/model/rigid_body_kinematics.hpp"
#include "ancfnet/state/rigid_body_state.hpp"

namespace ancfnet {
namespace {

// The net's knots and the nodes of its threads (m): the points whose hull encloses the target.
std::vector<Vector3d> NetPoints(const Model& model, const Net& net, const VectorXd& q) {
  std::vector<Vector3d> points;
  for (Index knot : net.knots) points.push_back(q.segment<3>(model.point_masses()[knot].dof));
  for (Index thread : net.threads) {
    const Cable& cable = model.cables()[thread];
    for (Index node = cable.first_node; node <= cable.first_node + cable.num_elements; ++node)
      points.push_back(q.segment<3>(model.NodePositionDof(node)));
  }
  return points;
}

// Where the target's bounding ball is and how fast its centre moves (world).
struct TargetBall {
  Vector3d center = Vector3d::Zero();
  Vector3d velocity = Vector3d::Zero();
  double radius = 0.0;
};

TargetBall CalcTargetBall(const Model& model, const State& state, const ContactTarget& target) {
  const TargetBoundingSphere bound = CalcTargetBoundingSphere(target);
  TargetBall ball{.center = bound.center, .radius = bound.radius};
  if (target.body < 0) return ball;
  const BodyPose pose = CalcBodyPose(model, state, target.body);
  const BodyVelocity v = CalcBodyVelocity(model.rigid_bodies()[target.body], state.v);
  // ṗ = ẋ_WB + R_WB (ω_B × s_B) for the body point s_B.
  ball.center = pose.p_WB + pose.R_WB * bound.center;
  ball.velocity = v.v_WB + pose.R_WB * v.w_B.cross(bound.center);
  return ball;
}

void CalcTensions(const Model& model, const Net& net, const VectorXd& q, CaptureMetrics* metrics) {
  if (!net.threads.empty()) metrics->thread_tension = CalcMaxThreadTension(model, net, q).tension;
  for (Index thread : net.threads)
    metrics->thread_breaking_force =
        std::min(metrics->thread_breaking_force, model.cables()[thread].breaking_force);
  const std::string tether_name = net.name + ".tether";
  for (const Cable& cable : model.cables()) {
    if (cable.name != tether_name) continue;
    metrics->has_tether = true;
    metrics->tether_tension = CalcCableMaxTension(model, cable, q);
    metrics->tether_breaking_force = cable.breaking_force;
  }
}

}  // namespace

ContactCoverage CalcContactCoverage(const Model& model, const Net& net, Index target,
                                    const std::vector<ContactPoint>& contacts) {
  std::set<Index> knots;
  std::set<Index> threads;
  for (const ContactPoint& c : contacts) {
    if (c.target != target) continue;
    if (c.point_mass >= 0 &&
        std::find(net.knots.begin(), net.knots.end(), c.point_mass) != net.knots.end())
      knots.insert(c.point_mass);
    if (c.element < 0) continue;
    const Index cable = model.elements()[c.element].cable;
    if (std::find(net.threads.begin(), net.threads.end(), cable) != net.threads.end())
      threads.insert(cable);
  }
  ContactCoverage coverage;
  coverage.in_contact = !knots.empty() || !threads.empty();
  if (!net.knots.empty())
    coverage.knot_coverage = static_cast<double>(knots.size()) / net.knots.size();
  if (!net.threads.empty())
    coverage.thread_coverage = static_cast<double>(threads.size()) / net.threads.size();
  return coverage;
}

double CalcSafetyFactor(double breaking_force, double max_tension) {
  if (!(max_tension > 0.0) || std::isinf(breaking_force))
    return std::numeric_limits<double>::infinity();
  return breaking_force / max_tension;
}

double CalcLoadRatio(double max_tension, double breaking_force) {
  if (std::isinf(breaking_force) || !(max_tension > 0.0)) return 0.0;
  return max_tension / breaking_force;
}

bool IsTargetEscaping(bool centre_inside_hull, const Vector3d& p_T, const Vector3d& v_T,
                      const Vector3d& p_N, const Vector3d& v_N) {
  return !centre_inside_hull && (v_T - v_N).dot(p_T - p_N) > 0.0;
}

CaptureMetrics CalcCaptureMetrics(const Model& model, const State& state, Index net_index,
                                  Index target, const std::vector<ContactPoint>& contacts,
                                  double initial_mouth_area) {
  const Net& net = model.nets()[net_index];
  CaptureMetrics metrics;
  const ContactCoverage coverage = CalcContactCoverage(model, net, target, contacts);
  metrics.in_contact = coverage.in_contact;
  metrics.knot_coverage = coverage.knot_coverage;
  metrics.thread_coverage = coverage.thread_coverage;
  CalcTensions(model, net, state.q, &metrics);
  if (initial_mouth_area > 0.0)
    metrics.mouth_area_ratio = CalcNetMouthArea(model, net, state.q) / initial_mouth_area;
  const ConvexHull hull(NetPoints(model, net, state.q));
  const TargetBall ball = CalcTargetBall(model, state, model.contact().targets[target]);
  metrics.enclosed_fraction = hull.CalcBallFractionInside(ball.center, ball.radius);
  metrics.escaped =
      IsTargetEscaping(hull.Contains(ball.center), ball.center, ball.velocity,
                       CalcNetCentroid(model, net, state.q), CalcNetCentroid(model, net, state.v));
  return metrics;
}

}  // namespace ancfnet
