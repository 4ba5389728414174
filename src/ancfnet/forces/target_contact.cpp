#include "ancfnet/forces/target_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ancfnet/contact/elastic_step_force.hpp"
#include "ancfnet/forces/impact_speed.hpp"
#include "ancfnet/model/cable_element_box.hpp"

namespace ancfnet {
namespace {

// A pair's penetration where it is farther from its target than its probe's radius and the
// exact value has not been needed.
constexpr double kFar = std::numeric_limits<double>::infinity();

// CalcElasticStepForce's least displacement, per metre of a probe's radius.
constexpr double kLeastDisplacement = 1e-6;

// The generalised weights of the point c(t) = (1 − t) r(ξ₀) + t r(ξ₁) of a probe's axis.
Vector4d CalcWeights(const ContactProbe& probe, double t) {
  return (1.0 - t) * probe.shape0 + t * probe.shape1;
}

}  // namespace

// The centre-line box of the element a run of probes lies on (MakeContactProbes puts the probes
// of an element one after another), found once per element as a loop goes through them.
class TargetContact::ElementBoxes {
 public:
  ElementBoxes(const Model& model, const VectorXd& q) : model_(model), q_(q) {}
  const Aabb& Of(Index element) {
    if (element != element_) {
      element_ = element;
      box_ = CalcCableElementBox(model_, element, q_);
    }
    return box_;
  }

 private:
  const Model& model_;
  const VectorXd& q_;
  Index element_ = -1;
  Aabb box_;
};

bool TargetContact::MayReach(const ContactProbe& probe, ElementBoxes& boxes, const Frame& frame) {
  if (probe.element < 0) return true;
  // The box holds every probe axis of the element: farther from the target's ball than the
  // probe's radius, none of them reaches the target (FindProbePointWithin's first test, for the
  // whole element and before its axes are located).
  constexpr double kRounding = 1e-9;  // m
  const double limit = frame.bound_radius + probe.radius + kRounding;
  return boxes.Of(probe.element).SquaredDistanceTo(frame.bound_center) <= limit * limit;
}

TargetContact::TargetContact(const Model& model)
    : model_(model),
      probes_(MakeContactProbes(model)),
      frames_(model.contact().targets.size()),
      distance_bounds_(probes_.size() * model.contact().targets.size()) {
  for (const ContactTarget& target : model.contact().targets)
    bounding_spheres_.push_back(CalcTargetBoundingSphere(target));
}

TargetContact::Frame TargetContact::CalcFrame(std::size_t t, const VectorXd& q,
                                              const VectorXd& v) const {
  const ContactTarget& target = model_.contact().targets[t];
  Frame frame;
  frame.bound_center = bounding_spheres_[t].center;
  frame.bound_radius = bounding_spheres_[t].radius;
  if (target.body < 0) return frame;
  const RigidBody& body = model_.rigid_bodies()[target.body];
  frame.body = target.body;
  frame.pose = CalcBodyPose(
      body, q, body_rotation_ ? (*body_rotation_)[target.body] : body.initial_orientation);
  frame.velocity = CalcBodyVelocity(body, v);
  frame.bound_center = frame.pose.p_WB + frame.pose.R_WB * frame.bound_center;
  return frame;
}

Index TargetContact::ProbeOwner(const ContactProbe& probe) const {
  return probe.element >= 0 ? probe.element
                            : static_cast<Index>(model_.elements().size()) + probe.point_mass;
}

TargetContact::TargetAxis TargetContact::InTargetFrame(const Frame& frame, const Axis& axis) {
  if (frame.body < 0) return {axis.x0, axis.x1};
  // In the body's frame: x_B = R_WBᵀ (x − x_WB).
  const Matrix3d& R = frame.pose.R_WB;
  return {R.transpose() * (axis.x0 - frame.pose.p_WB), R.transpose() * (axis.x1 - frame.pose.p_WB)};
}

TargetContact::ProbePoint TargetContact::FindProbePoint(const ContactTarget& target,
                                                        const Frame& frame,
                                                        const Axis& axis) const {
  return FindProbePoint(target, frame, axis, InTargetFrame(frame, axis));
}

TargetContact::ProbePoint TargetContact::FindProbePoint(const ContactTarget& target,
                                                        const Frame& frame, const Axis& axis,
                                                        const TargetAxis& ends) const {
  ProbePoint point;
  SegmentTargetDistance d = CalcSegmentTargetDistance(target, ends.x0, ends.x1);
  if (frame.body >= 0) {
    // n = R_WB n_B, ∂n/∂x = R_WB H_B R_WBᵀ.
    const Matrix3d& R = frame.pose.R_WB;
    d.normal = R * d.normal;
    d.hessian = R * d.hessian * R.transpose();
  }
  point.t = d.t;
  point.x = (1.0 - d.t) * axis.x0 + d.t * axis.x1;
  point.x_dot = (1.0 - d.t) * axis.v0 + d.t * axis.v1;
  point.axis = axis.x1 - axis.x0;
  point.axis_rate = axis.v1 - axis.v0;
  point.distance = d;
  point.distance_lower_bound = d.lower_bound;
  return point;
}

std::optional<TargetContact::ProbePoint> TargetContact::FindProbePointWithin(
    std::size_t pair, const ContactTarget& target, const Frame& frame, const Axis& axis,
    double reach) const {
  // The axis lies in the box its ends span and the target in its ball: the distance of the box
  // from the ball is a lower bound of theirs, without a square root and without moving the axis
  // into the target's frame (the test that runs for every probe and target at every residual).
  const double outside2 =
      Aabb::OfCapsule(axis.x0, axis.x1, 0.0, 0.0).SquaredDistanceTo(frame.bound_center);
  const double limit = frame.bound_radius + reach;
  if (limit < 0.0 || outside2 > limit * limit) return std::nullopt;
  const TargetAxis ends = InTargetFrame(frame, axis);
  SegmentDistanceBound& bound = distance_bounds_[pair];
  if (bound.ShowsFartherThan(ends.x0, ends.x1, reach)) return std::nullopt;
  ProbePoint point = FindProbePoint(target, frame, axis, ends);
  // Not the distance found, which for a capsule over a mesh may be a local minimum, but a bound
  // of the global one.
  bound = {ends.x0, ends.x1, point.distance_lower_bound};
  return point;
}

ContactKinematics TargetContact::CalcKinematics(const Frame& frame, const ContactProbe& probe,
                                                const ProbePoint& point) const {
  ContactKinematics k;
  k.velocity = point.x_dot;
  const TargetDistance& gap = point.distance;
  if (frame.body >= 0) {
    // The surface point s moves with the body at ẋ_WB + R_WB (ω_B × R_WBᵀ (s − x_WB)).
    const Matrix3d& R = frame.pose.R_WB;
    const Vector3d s = point.x - gap.distance * gap.normal;
    k.velocity -=
        frame.velocity.v_WB + R * frame.velocity.w_B.cross(R.transpose() * (s - frame.pose.p_WB));
  }
  k.penetration = probe.radius - gap.distance;
  k.normal = gap.normal;
  k.normal_derivative = gap.hessian;
  return k;
}

TargetContact::PairForce TargetContact::CalcPairForce(const Frame& frame, const ContactProbe& probe,
                                                      const ProbePoint& point,
                                                      const ContactPairHistory& history,
                                                      bool with_jacobian) const {
  const ContactKinematics kinematics = CalcKinematics(frame, probe, point);
  // history.speed > 0: the impact speed frozen at first touch; ≤ 0: apart at the last accepted
  // state, closing at −history.speed (a constant through this step's Newton iterations). The
  // bristle of a target on a body turns with it: z_W = R_WB z_B, R_WB at (q, v).
  const Vector3d bristle =
      frame.body < 0 ? history.bristle : Vector3d(frame.pose.R_WB * history.bristle);
  const ContactSpec& spec = model_.contact();
  PairForce r;
  static_cast<ContactPairForce&>(r) = CalcContactPairForce(
      spec.normal, spec.friction, kinematics, history.speed, bristle, step_, with_jacobian);
  if (frame.body >= 0) r.bristle = frame.pose.R_WB.transpose() * r.bristle;
  r.t = point.t;
  r.surface_point = point.x - (probe.radius - kinematics.penetration) * kinematics.normal;
  r.normal = kinematics.normal;
  // The geometry also for a pair apart at the midpoint: after SetStep its elastic force acts
  // while it touches at either end of the step.
  if (!with_jacobian) return r;
  TargetPairGeometry& g = r.geometry;
  if (probe.element >= 0) {
    g.num_blocks = 4;
    g.weights = CalcWeights(probe, point.t);
    g.weight_rates = probe.shape1 - probe.shape0;
  }
  // An interior minimum where φ is smooth (φ' = n·Δ ≈ 0, φ'' > 0): t* moves with the positions.
  const double slope = point.distance.normal.dot(point.axis);
  const double curvature = point.axis.dot(point.distance.hessian * point.axis);
  g.moving_point = point.t > 0.0 && point.t < 1.0 && curvature > 0.0 &&
                   std::abs(slope) <= 1e-9 * point.axis.norm();
  g.axis = point.axis;
  g.axis_rate = point.axis_rate;
  g.point = point.x;
  g.distance = point.distance.distance;
  g.normal = point.distance.normal;
  g.hessian = point.distance.hessian;
  if (frame.body >= 0) {
    g.on_body = true;
    g.pose = frame.pose;
    g.angular_velocity = frame.pose.R_WB * frame.velocity.w_B;
    g.bristle = bristle;
  }
  return r;
}

bool TargetContact::MayCouple(const Frame& frame, const Axis& axis, double reach, double lead) {
  // The test below without the distance query: the axis is at least the distance of the box its
  // ends span from the target's ball, less the ball's radius, away; its points move at most as
  // fast as its faster end, and the body's velocity at such a point, ẋ_WB + ω × (x − x_WB), is
  // at most |ẋ_WB| + |ω| max_k |x_k − x_WB|.
  const double outside =
      std::sqrt(Aabb::OfCapsule(axis.x0, axis.x1, 0.0, 0.0).SquaredDistanceTo(frame.bound_center));
  const double speed = std::max(axis.v0.norm(), axis.v1.norm()) + frame.velocity.v_WB.norm() +
                       frame.velocity.w_B.norm() * std::max((axis.x0 - frame.pose.p_WB).norm(),
                                                            (axis.x1 - frame.pose.p_WB).norm());
  constexpr double kRounding = 1e-9;  // m
  return !(outside - frame.bound_radius - kRounding > reach + lead * speed);
}

void TargetContact::FindBodyCouplings(const VectorXd& q, const VectorXd& v, double h,
                                      const SystemMatrix& matrix,
                                      std::vector<std::pair<Index, Index>>* owners) const {
  owners->clear();
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (targets[t].body < 0) continue;
    const Frame frame = CalcFrame(t, q, v);
    const Index body_owner = matrix.BodyOwner(frame.body);
    for (const ContactProbe& probe : probes_) {
      const Axis axis = LocateCapsuleAxis(model_, probe, q, &v);
      if (!MayCouple(frame, axis, 1.5 * probe.radius, 2.0 * h)) continue;
      const ProbePoint point = FindProbePoint(targets[t], frame, axis);
      const Matrix3d& R = frame.pose.R_WB;
      const Vector3d body_velocity =
          frame.velocity.v_WB +
          R * frame.velocity.w_B.cross(R.transpose() * (point.x - frame.pose.p_WB));
      if (point.distance.distance <
          1.5 * probe.radius + 2.0 * h * (point.x_dot - body_velocity).norm())
        owners->emplace_back(ProbeOwner(probe), body_owner);
    }
  }
}

template <class Visit>
void TargetContact::ForEachTouchingPair(const VectorXd& q, const VectorXd& v,
                                        const std::vector<ContactPairHistory>& history,
                                        bool with_jacobian, Visit&& visit) const {
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) frames_[t] = CalcFrame(t, q, v);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const Axis axis = LocateCapsuleAxis(model_, probes_[p], q, &v);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const std::size_t pair = p * targets.size() + t;
      const std::optional<ProbePoint> point =
          FindProbePointWithin(pair, targets[t], frames_[t], axis, probes_[p].radius);
      if (!point) continue;
      PairForce f = CalcPairForce(frames_[t], probes_[p], *point, history[pair], with_jacobian);
      if (!f.touching) continue;
      f.target = static_cast<Index>(t);
      visit(probes_[p], f);
    }
  }
}

void TargetContact::SetStep(const VectorXd& q_start, const VectorXd& v_start,
                            const VectorXd* q_end) {
  step_start_ = &q_start;
  step_start_velocity_ = &v_start;
  step_end_ = q_end;
  const auto& targets = model_.contact().targets;
  start_penetration_.assign(probes_.size() * targets.size(), -kFar);
  for (std::size_t t = 0; t < targets.size(); ++t) frames_[t] = CalcFrame(t, q_start, v_start);
  ElementBoxes boxes(model_, q_start);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    std::optional<Axis> axis;  // located for the first target the element may reach
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (!MayReach(probes_[p], boxes, frames_[t])) continue;
      if (!axis) axis = LocateCapsuleAxis(model_, probes_[p], q_start);
      const std::size_t pair = p * targets.size() + t;
      const std::optional<ProbePoint> point =
          FindProbePointWithin(pair, targets[t], frames_[t], *axis, probes_[p].radius);
      if (point) start_penetration_[pair] = probes_[p].radius - point->distance.distance;
    }
  }
}

void TargetContact::AddForces(const VectorXd& q, const VectorXd& v,
                              const std::vector<ContactPairHistory>& history, Workspace& ws) const {
  if (step_end_) {
    AddStepForces(q, v, history, ws);
    return;
  }
  ws.contact_energy = 0.0;
  ForEachTouchingPair(q, v, history, false, [&](const ContactProbe& probe, const PairForce& f) {
    ws.contact_energy += f.energy;
    ApplyPairForce(probe, f, ws);
  });
}

void TargetContact::BeginStepEvaluation(const VectorXd& q, const VectorXd& v) const {
  const auto& targets = model_.contact().targets;
  end_frames_.resize(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    frames_[t] = CalcFrame(t, q, v);
    end_frames_[t] = CalcFrame(t, *step_end_, v);
  }
}

std::optional<TargetContact::PairForce> TargetContact::CalcStepPairForce(
    std::size_t p, std::size_t t, const Axis& axis, const Axis& end_axis,
    const ContactPairHistory& history, bool with_jacobian, double* energy) const {
  const ContactTarget& target = model_.contact().targets[t];
  const ContactProbe& probe = probes_[p];
  const std::size_t pair = p * model_.contact().targets.size() + t;
  const std::optional<ProbePoint> end =
      FindProbePointWithin(pair, target, end_frames_[t], end_axis, probe.radius);
  double end_depth = end ? probe.radius - end->distance.distance : -kFar;
  double& start_depth = start_penetration_[pair];
  if (!(end_depth > 0.0) && !(start_depth > 0.0)) {
    // Apart at both ends: Φ does not change, no elastic force; the damping and friction of a
    // pair touching at the midpoint only still act.
    const std::optional<ProbePoint> mid =
        FindProbePointWithin(pair, target, frames_[t], axis, probe.radius);
    if (!mid) return std::nullopt;
    PairForce f = CalcPairForce(frames_[t], probe, *mid, history, with_jacobian);
    if (!f.touching) return std::nullopt;
    f.target = static_cast<Index>(t);
    f.force = f.dissipative;
    // Nor its slope (∂δ/∂x = −nᵀ).
    if (with_jacobian) f.dforce_dx += ElasticSlope(f.penetration) * f.normal * f.normal.transpose();
    return f;
  }
  // One end beyond its probe's radius: its exact penetration, for F̄'s divided difference.
  if (start_depth == -kFar) {
    const Frame start = CalcFrame(t, *step_start_, *step_start_velocity_);
    const Axis start_axis = LocateCapsuleAxis(model_, probe, *step_start_);
    start_depth = probe.radius - FindProbePoint(target, start, start_axis).distance.distance;
  }
  if (end_depth == -kFar)
    end_depth =
        probe.radius - FindProbePoint(target, end_frames_[t], end_axis).distance.distance;
  const NormalLaw& law = model_.contact().normal;
  *energy += law.CalcElasticEnergy(end_depth);
  PairForce f = CalcPairForce(frames_[t], probe, FindProbePoint(target, frames_[t], axis),
                              history, with_jacobian);
  f.target = static_cast<Index>(t);
  f.force = f.dissipative + CalcElasticStepForce(law, start_depth, end_depth, f.normal,
                                                 CalcStepDisplacement(probe, f),
                                                 kLeastDisplacement * probe.radius);
  if (with_jacobian) {
    // F̄ depends on the end of the step, which moves twice as far as the midpoint: the elastic
    // slope at the midpoint gives way to 2 ∂F̄/∂δ₁ (∂δ/∂x = −nᵀ).
    const double slope = 2.0 * CalcElasticStepMagnitude(law, start_depth, end_depth).dforce_dend -
                         (f.touching ? ElasticSlope(f.penetration) : 0.0);
    f.dforce_dx -= slope * f.normal * f.normal.transpose();
  }
  return f;
}

double TargetContact::ElasticSlope(double penetration) const {
  return model_.contact().normal.Evaluate(penetration, 0.0, 1.0).dforce_ddelta;
}

template <class Visit>
void TargetContact::ForEachStepPair(const VectorXd& q, const VectorXd& v,
                                    const std::vector<ContactPairHistory>& history,
                                    bool with_jacobian, double* energy, Visit&& visit) const {
  BeginStepEvaluation(q, v);
  const std::size_t num_targets = model_.contact().targets.size();
  // The probes of an element come one after another (MakeContactProbes): its boxes at q and at
  // the step's end hold all their axes. A pair whose probe's box is farther from the target's
  // ball than its radius at both, and that did not touch at the start, has no force
  // (CalcStepPairForce would find it beyond reach at the end and at q): it is skipped, and so
  // is a probe without such a pair, before its axes are located.
  ElementBoxes boxes(model_, q), end_boxes(model_, *step_end_);
  const auto may_touch = [&](std::size_t p, std::size_t t) {
    return start_penetration_[p * num_targets + t] > 0.0 ||
           MayReach(probes_[p], boxes, frames_[t]) ||
           MayReach(probes_[p], end_boxes, end_frames_[t]);
  };
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const ContactProbe& probe = probes_[p];
    std::optional<Axis> axis, end_axis;  // located for the first target the probe may touch
    for (std::size_t t = 0; t < num_targets; ++t) {
      if (!may_touch(p, t)) continue;
      if (!axis) {
        axis = LocateCapsuleAxis(model_, probe, q, &v);
        end_axis = LocateCapsuleAxis(model_, probe, *step_end_);
      }
      const std::optional<PairForce> f = CalcStepPairForce(
          p, t, *axis, *end_axis, history[p * num_targets + t], with_jacobian, energy);
      if (f) visit(probe, *f);
    }
  }
}

void TargetContact::AddStepForces(const VectorXd& q, const VectorXd& v,
                                  const std::vector<ContactPairHistory>& history,
                                  Workspace& ws) const {
  ws.contact_energy = 0.0;
  ForEachStepPair(
      q, v, history, false, &ws.contact_energy,
      [&](const ContactProbe& probe, const PairForce& f) { ApplyPairForce(probe, f, ws); });
}

void TargetContact::AddStepJacobian(const VectorXd& q, const VectorXd& v,
                                    const std::vector<ContactPairHistory>& history,
                                    const IterationWeights& weights, SystemMatrix* matrix) const {
  double energy = 0.0;
  ForEachStepPair(q, v, history, true, &energy, [&](const ContactProbe& probe, const PairForce& f) {
    AddPairJacobian(probe, f, weights, matrix);
  });
}

Vector3d TargetContact::CalcStepDisplacement(const ContactProbe& probe, const PairForce& f) const {
  const VectorXd& q0 = *step_start_;
  const VectorXd& q1 = *step_end_;
  Vector3d d = Vector3d::Zero();
  if (probe.element < 0) {
    const Index dof = model_.point_masses()[probe.point_mass].dof;
    d = q1.segment<3>(dof) - q0.segment<3>(dof);
  } else {
    const CableElement& element = model_.elements()[probe.element];
    const Vector4d w = CalcWeights(probe, f.t);
    for (int k = 0; k < 4; ++k) {
      const Index dof = element.dofs[3 * k];
      d += w[k] * (q1.segment<3>(dof) - q0.segment<3>(dof));
    }
  }
  const Frame& frame = frames_[f.target];
  if (frame.body < 0) return d;
  const RigidBody& body = model_.rigid_bodies()[frame.body];
  Vector6d moved;
  moved << q1.segment<3>(body.position_dof()) - q0.segment<3>(body.position_dof()),
      q1.segment<3>(body.rotation_dof()) - q0.segment<3>(body.rotation_dof());
  return d - CalcPointVelocityMap(frame.pose, f.surface_point) * moved;
}

void TargetContact::ApplyPairForce(const ContactProbe& probe, const PairForce& f,
                                   Workspace& ws) const {
  if (probe.element < 0) {
    const Index dof = model_.point_masses()[probe.point_mass].dof;
    ws.internal_force.segment<3>(dof) -= f.force;
    ws.viscous_force.segment<3>(dof) -= f.dissipative;
  } else {
    const CableElement& element = model_.elements()[probe.element];
    const Vector4d w = CalcWeights(probe, f.t);
    for (int k = 0; k < 4; ++k) {
      const Index dof = element.dofs[3 * k];
      ws.internal_force.segment<3>(dof) -= w[k] * f.force;
      ws.viscous_force.segment<3>(dof) -= w[k] * f.dissipative;
    }
  }
  const Frame& frame = frames_[f.target];
  if (frame.body < 0) return;
  // The body feels −f at the contact point: Q_body = Gᵀ (−f).
  const RigidBody& body = model_.rigid_bodies()[frame.body];
  const Matrix3x6d G = CalcPointVelocityMap(frame.pose, f.surface_point);
  const Vector6d force = G.transpose() * f.force;
  const Vector6d dissipative = G.transpose() * f.dissipative;
  ws.internal_force.segment<3>(body.position_dof()) += force.head<3>();
  ws.internal_force.segment<3>(body.rotation_dof()) += force.tail<3>();
  ws.viscous_force.segment<3>(body.position_dof()) += dissipative.head<3>();
  ws.viscous_force.segment<3>(body.rotation_dof()) += dissipative.tail<3>();
}

void TargetContact::AddJacobian(const VectorXd& q, const VectorXd& v,
                                const std::vector<ContactPairHistory>& history,
                                const IterationWeights& weights, SystemMatrix* matrix) const {
  if (step_end_) {
    AddStepJacobian(q, v, history, weights, matrix);
    return;
  }
  ForEachTouchingPair(q, v, history, true, [&](const ContactProbe& probe, const PairForce& f) {
    AddPairJacobian(probe, f, weights, matrix);
  });
}

void TargetContact::AddPairJacobian(const ContactProbe& probe, const PairForce& f,
                                    const IterationWeights& weights, SystemMatrix* matrix) const {
  const Matrix18d jacobian =
      CalcTargetPairJacobian(f.geometry, f, weights.stiffness, weights.damping);
  if (probe.element < 0)
    matrix->AddPointMassBlock(probe.point_mass, jacobian.topLeftCorner<3, 3>());
  else
    matrix->AddElementBlock(probe.element, jacobian.topLeftCorner<12, 12>());
  const Frame& frame = frames_[f.target];
  if (frame.body < 0) return;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      matrix->AddBodyBlock(frame.body, i, j, jacobian.block<3, 3>(12 + 3 * i, 12 + 3 * j));
  const int coupling =
      matrix->FindContactCoupling(ProbeOwner(probe), matrix->BodyOwner(frame.body));
  if (coupling < 0) return;
  const int num_blocks = f.geometry.num_blocks;
  for (int i = 0; i < num_blocks; ++i)
    for (int j = 0; j < 2; ++j) {
      matrix->AddContactBlock(coupling, i, num_blocks + j,
                              jacobian.block<3, 3>(3 * i, 12 + 3 * j));
      matrix->AddContactBlock(coupling, num_blocks + j, i,
                              jacobian.block<3, 3>(12 + 3 * j, 3 * i));
    }
}

void TargetContact::UpdateHistory(const VectorXd& q, const VectorXd& v,
                                  std::vector<ContactPairHistory>* history) const {
  const auto& targets = model_.contact().targets;
  const bool bristles =
      model_.contact().friction && model_.contact().friction->kind == FrictionLawKind::kLuGre;
  for (std::size_t t = 0; t < targets.size(); ++t) frames_[t] = CalcFrame(t, q, v);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const Axis axis = LocateCapsuleAxis(model_, probes_[p], q, &v);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      ContactPairHistory& stored = (*history)[p * targets.size() + t];
      const ProbePoint point = FindProbePoint(targets[t], frames_[t], axis);
      const ContactKinematics k = CalcKinematics(frames_[t], probes_[p], point);
      const double closing = std::max(-k.normal.dot(k.velocity), 0.0);
      // The bristle at the end of the step, from the history at its start.
      stored.bristle = bristles
                           ? CalcPairForce(frames_[t], probes_[p], point, stored, false).bristle
                           : Vector3d::Zero();
      UpdateImpactSpeed(k.penetration > 0.0, closing, model_.contact().normal.min_approach_speed,
                        &stored);
    }
  }
}

std::string TargetContact::CheckStep(const VectorXd& q_start, const VectorXd& v_start,
                                     const VectorXd& q, const VectorXd& v) const {
  const double fraction = model_.contact().penetration_increment;
  if (!(fraction > 0.0)) return {};
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Frame start = CalcFrame(t, q_start, v_start);
    const Frame end = CalcFrame(t, q, v);
    ElementBoxes boxes(model_, q);
    for (std::size_t p = 0; p < probes_.size(); ++p) {
      const ContactProbe& probe = probes_[p];
      if (!MayReach(probe, boxes, end)) continue;
      const std::optional<ProbePoint> point =
          FindProbePointWithin(p * targets.size() + t, targets[t], end,
                               LocateCapsuleAxis(model_, probe, q), probe.radius);
      if (!point) continue;
      const double depth = probe.radius - point->distance.distance;
      const double limit = fraction * probe.radius;
      if (!(depth > limit)) continue;
      const double depth_start =
          probe.radius -
          FindProbePoint(targets[t], start, LocateCapsuleAxis(model_, probe, q_start))
              .distance.distance;
      if (depth - std::max(depth_start, 0.0) <= limit) continue;
      const std::string where =
          probe.element >= 0 ? fmt::format("element {} at ξ = {:.3f}", probe.element,
                                           (1.0 - point->t) * probe.xi0 + point->t * probe.xi1)
                             : fmt::format("point mass {}", probe.point_mass);
      return fmt::format(
          "the contact probe of {} sank {:.3g} m into target '{}' in one step (more than {} "
          "of its radius)",
          where, depth - std::max(depth_start, 0.0), targets[t].name, fraction);
    }
  }
  return {};
}

TargetContact::Summary TargetContact::Summarize(
    const VectorXd& q, const VectorXd& v, const std::vector<ContactPairHistory>& history) const {
  Summary s;
  ForEachTouchingPair(q, v, history, false, [&](const ContactProbe&, const ContactPairForce& f) {
    ++s.active;
    s.normal_force += f.normal_force;
    s.max_penetration = std::max(s.max_penetration, f.penetration);
  });
  return s;
}

void TargetContact::CollectContacts(const VectorXd& q, const VectorXd& v,
                                    const std::vector<ContactPairHistory>& history,
                                    std::vector<ContactPoint>* out) const {
  ForEachTouchingPair(q, v, history, false, [&](const ContactProbe& probe, const PairForce& f) {
    out->push_back({.point_W = f.surface_point,
                    .normal_W = f.normal,
                    .penetration = f.penetration,
                    .normal_force = f.normal_force,
                    .friction_force_W = f.friction,
                    .force_W = f.force,
                    .target = f.target,
                    .element = probe.element,
                    .point_mass = probe.point_mass,
                    .xi = (1.0 - f.t) * probe.xi0 + f.t * probe.xi1});
  });
}

}  // namespace ancfnet
