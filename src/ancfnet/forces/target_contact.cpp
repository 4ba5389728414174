#include "ancfnet/forces/target_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/contact/distance/point_box.hpp"
#include "ancfnet/contact/distance/point_capsule.hpp"
#include "ancfnet/contact/distance/point_cylinder.hpp"
#include "ancfnet/contact/distance/point_plane.hpp"
#include "ancfnet/contact/distance/point_sphere.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {
namespace {

// Signed distance of a point to a target's surface, its outward normal and ∂n/∂x.
struct Gap {
  double distance = 0.0;
  Vector3d normal = Vector3d::UnitZ();
  Matrix3d hessian = Matrix3d::Zero();
};

Gap CalcGap(const ContactTarget& t, const Vector3d& x) {
  switch (t.kind) {
    case ContactTarget::Kind::kPlane: {
      const PointPlaneDistance d = CalcPointPlaneDistance(x, t.point, t.normal);
      return {d.distance, d.gradient_p, Matrix3d::Zero()};
    }
    case ContactTarget::Kind::kSphere: {
      const PointSphereDistance d = CalcPointSphereDistance(x, t.point, t.radius);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kBox: {
      const PointBoxDistance d = CalcPointBoxDistance(x, t.point, t.half_extents, t.rotation);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kCylinder: {
      const PointCylinderDistance d =
          CalcPointCylinderDistance(x, t.point, t.normal, t.radius, t.half_length);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kCapsule: {
      const PointCapsuleDistance d =
          CalcPointCapsuleDistance(x, t.point, t.normal, t.half_length, t.radius);
      return {d.distance, d.normal, d.hessian};
    }
    case ContactTarget::Kind::kMesh: {
      const MeshDistance d = t.mesh->CalcDistance(x);
      return {d.distance, d.normal, d.hessian};
    }
  }
  return {};
}

// Automatic inspection spheres per element: one per diameter of length, 2 … 32.
int PointsPerElement(const ContactSpec& spec, double length, double radius) {
  if (spec.points_per_element > 0) return spec.points_per_element;
  const double per_diameter = radius > 0.0 ? length / (2.0 * radius) : 2.0;
  return static_cast<int>(std::clamp(std::ceil(per_diameter), 2.0, 32.0));
}

}  // namespace

std::vector<ContactProbe> MakeContactProbes(const Model& model) {
  const ContactSpec& spec = model.contact();
  std::vector<ContactProbe> probes;
  if (spec.targets.empty()) return probes;
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const CableElementParameters& p = elements[e].parameters;
    const double radius = spec.cable_radius > 0.0
                              ? spec.cable_radius
                              : model.cables()[elements[e].cable].properties.radius;
    const int n = PointsPerElement(spec, p.length, radius);
    for (int j = 0; j < n; ++j) {
      ContactProbe probe;
      probe.element = static_cast<Index>(e);
      probe.xi = (j + 0.5) / n;
      probe.shape = CalcHermiteShape(probe.xi, p.length).s;
      probe.radius = radius;
      probes.push_back(probe);
    }
  }
  for (std::size_t i = 0; i < model.point_masses().size(); ++i) {
    ContactProbe probe;
    probe.point_mass = static_cast<Index>(i);
    probe.radius = spec.point_mass_radius;
    probes.push_back(probe);
  }
  return probes;
}

Index CountContactPairs(const Model& model) {
  return static_cast<Index>(MakeContactProbes(model).size() * model.contact().targets.size());
}

TargetContact::TargetContact(const Model& model)
    : model_(model), probes_(MakeContactProbes(model)), frames_(model.contact().targets.size()) {}

TargetContact::Frame TargetContact::CalcFrame(const ContactTarget& target, const VectorXd& q,
                                              const VectorXd& v) const {
  Frame frame;
  if (target.body < 0) return frame;
  const RigidBody& body = model_.rigid_bodies()[target.body];
  frame.body = target.body;
  frame.pose = CalcBodyPose(
      body, q, body_rotation_ ? (*body_rotation_)[target.body] : body.initial_orientation);
  frame.velocity = CalcBodyVelocity(body, v);
  return frame;
}

Index TargetContact::ProbeOwner(const ContactProbe& probe) const {
  return probe.element >= 0 ? probe.element
                            : static_cast<Index>(model_.elements().size()) + probe.point_mass;
}

void TargetContact::Locate(const ContactProbe& probe, const VectorXd& q, const VectorXd& v,
                           Vector3d* x, Vector3d* x_dot) const {
  if (probe.element < 0) {
    const Index dof = model_.point_masses()[probe.point_mass].dof;
    *x = q.segment<3>(dof);
    *x_dot = v.segment<3>(dof);
    return;
  }
  const CableElement& element = model_.elements()[probe.element];
  x->setZero();
  x_dot->setZero();
  for (int k = 0; k < 4; ++k) {
    const Index dof = element.dofs[3 * k];
    *x += probe.shape[k] * q.segment<3>(dof);
    *x_dot += probe.shape[k] * v.segment<3>(dof);
  }
}

ContactKinematics TargetContact::CalcKinematics(const ContactTarget& target, const Frame& frame,
                                                const ContactProbe& probe, const Vector3d& x,
                                                const Vector3d& x_dot) const {
  ContactKinematics k;
  k.velocity = x_dot;
  Gap gap;
  if (frame.body < 0) {
    gap = CalcGap(target, x);
  } else {
    // In the body's frame: x_B = R_WBᵀ (x − x_WB); n = R_WB n_B, ∂n/∂x = R_WB H_B R_WBᵀ; the
    // surface point s moves with the body at ẋ_WB + R_WB (ω_B × R_WBᵀ (s − x_WB)).
    const Matrix3d& R = frame.pose.R_WB;
    const Gap local = CalcGap(target, R.transpose() * (x - frame.pose.p_WB));
    gap.distance = local.distance;
    gap.normal = R * local.normal;
    gap.hessian = R * local.hessian * R.transpose();
    const Vector3d s = x - gap.distance * gap.normal;
    k.velocity -=
        frame.velocity.v_WB + R * frame.velocity.w_B.cross(R.transpose() * (s - frame.pose.p_WB));
  }
  k.penetration = probe.radius - gap.distance;
  k.normal = gap.normal;
  k.normal_derivative = gap.hessian;
  return k;
}

TargetContact::PairForce TargetContact::CalcPairForce(const ContactTarget& target,
                                                      const Frame& frame, const ContactProbe& probe,
                                                      const Vector3d& x, const Vector3d& x_dot,
                                                      const ContactPairHistory& history,
                                                      bool with_jacobian) const {
  const ContactKinematics kinematics = CalcKinematics(target, frame, probe, x, x_dot);
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
  r.surface_point = x - (probe.radius - kinematics.penetration) * kinematics.normal;
  r.normal = kinematics.normal;
  return r;
}

void TargetContact::FindBodyCouplings(const VectorXd& q, const VectorXd& v, double h,
                                      const SystemMatrix& matrix,
                                      std::vector<std::pair<Index, Index>>* owners) const {
  owners->clear();
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (targets[t].body < 0) continue;
    const Frame frame = CalcFrame(targets[t], q, v);
    const Index body_owner = matrix.BodyOwner(frame.body);
    for (const ContactProbe& probe : probes_) {
      Vector3d x, x_dot;
      Locate(probe, q, v, &x, &x_dot);
      const Matrix3d& R = frame.pose.R_WB;
      const Gap gap = CalcGap(targets[t], R.transpose() * (x - frame.pose.p_WB));
      const Vector3d body_velocity =
          frame.velocity.v_WB + R * frame.velocity.w_B.cross(R.transpose() * (x - frame.pose.p_WB));
      if (gap.distance < 1.5 * probe.radius + 2.0 * h * (x_dot - body_velocity).norm())
        owners->emplace_back(ProbeOwner(probe), body_owner);
    }
  }
}

template <class Visit>
void TargetContact::ForEachTouchingPair(const VectorXd& q, const VectorXd& v,
                                        const std::vector<ContactPairHistory>& history,
                                        bool with_jacobian, Visit&& visit) const {
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) frames_[t] = CalcFrame(targets[t], q, v);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Vector3d x, x_dot;
    Locate(probes_[p], q, v, &x, &x_dot);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      PairForce f = CalcPairForce(targets[t], frames_[t], probes_[p], x, x_dot,
                                  history[p * targets.size() + t], with_jacobian);
      if (!f.touching) continue;
      f.target = static_cast<Index>(t);
      visit(probes_[p], f);
    }
  }
}

void TargetContact::AddForces(const VectorXd& q, const VectorXd& v,
                              const std::vector<ContactPairHistory>& history, Workspace& ws) const {
  ws.contact_energy = 0.0;
  ForEachTouchingPair(q, v, history, false, [&](const ContactProbe& probe, const PairForce& f) {
    ws.contact_energy += f.energy;
    if (probe.element < 0) {
      const Index dof = model_.point_masses()[probe.point_mass].dof;
      ws.internal_force.segment<3>(dof) -= f.force;
      ws.viscous_force.segment<3>(dof) -= f.dissipative;
    } else {
      const CableElement& element = model_.elements()[probe.element];
      for (int k = 0; k < 4; ++k) {
        const Index dof = element.dofs[3 * k];
        ws.internal_force.segment<3>(dof) -= probe.shape[k] * f.force;
        ws.viscous_force.segment<3>(dof) -= probe.shape[k] * f.dissipative;
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
  });
}

void TargetContact::AddJacobian(const VectorXd& q, const VectorXd& v,
                                const std::vector<ContactPairHistory>& history,
                                const IterationWeights& weights, SystemMatrix* matrix) const {
  ForEachTouchingPair(q, v, history, true, [&](const ContactProbe& probe, const PairForce& f) {
    // Q = −Sᵀ f(x − x_s): ∂Q/∂e = −Sᵀ (∂f/∂x) S, with B = −(c_K ∂f/∂x + c_C ∂f/∂ẋ).
    const Matrix3d block = -(weights.stiffness * f.dforce_dx + weights.damping * f.dforce_dv);
    const int num_blocks = probe.element < 0 ? 1 : 4;
    auto weight = [&](int i) { return probe.element < 0 ? 1.0 : probe.shape[i]; };
    if (probe.element < 0) {
      matrix->AddPointMassBlock(probe.point_mass, block);
    } else {
      Matrix12d element_block;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          element_block.block<3, 3>(3 * i, 3 * j) = probe.shape[i] * probe.shape[j] * block;
      matrix->AddElementBlock(probe.element, element_block);
    }
    const Frame& frame = frames_[f.target];
    if (frame.body < 0) return;
    // The contact point moves with the body as G (ẋ_WB, ω_B): probe–body blocks −Wᵀ B G and
    // −Gᵀ B W, body–body Gᵀ B G (G held fixed: its change with the rotation is left out).
    const Matrix3x6d G = CalcPointVelocityMap(frame.pose, f.surface_point);
    const Matrix3d g[2] = {G.leftCols<3>(), G.rightCols<3>()};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        matrix->AddBodyBlock(frame.body, i, j, g[i].transpose() * block * g[j]);
    const int coupling =
        matrix->FindContactCoupling(ProbeOwner(probe), matrix->BodyOwner(frame.body));
    if (coupling < 0) return;
    for (int i = 0; i < num_blocks; ++i)
      for (int j = 0; j < 2; ++j) {
        matrix->AddContactBlock(coupling, i, num_blocks + j, block * g[j], -weight(i));
        matrix->AddContactBlock(coupling, num_blocks + j, i, g[j].transpose() * block, -weight(i));
      }
  });
}

void TargetContact::UpdateHistory(const VectorXd& q, const VectorXd& v,
                                  std::vector<ContactPairHistory>* history) const {
  const auto& targets = model_.contact().targets;
  const bool bristles =
      model_.contact().friction && model_.contact().friction->kind == FrictionLawKind::kLuGre;
  for (std::size_t t = 0; t < targets.size(); ++t) frames_[t] = CalcFrame(targets[t], q, v);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Vector3d x, x_dot;
    Locate(probes_[p], q, v, &x, &x_dot);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      ContactPairHistory& stored = (*history)[p * targets.size() + t];
      const ContactKinematics k = CalcKinematics(targets[t], frames_[t], probes_[p], x, x_dot);
      const double closing = std::max(-k.normal.dot(k.velocity), 0.0);
      // The bristle at the end of the step, from the history at its start.
      stored.bristle =
          bristles
              ? CalcPairForce(targets[t], frames_[t], probes_[p], x, x_dot, stored, false).bristle
              : Vector3d::Zero();
      if (!(k.penetration > 0.0)) {
        stored.speed = -closing;  // apart: remember how fast it closes in
      } else if (stored.speed <= 0.0) {
        // Just touched: its impact speed is the closing speed before the touch.
        stored.speed =
            std::max(std::max(-stored.speed, closing), model_.contact().normal.min_approach_speed);
      }
    }
  }
}

std::string TargetContact::CheckStep(const VectorXd& q_start, const VectorXd& v_start,
                                     const VectorXd& q, const VectorXd& v) const {
  const double fraction = model_.contact().penetration_increment;
  if (!(fraction > 0.0)) return {};
  const auto& targets = model_.contact().targets;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Frame start = CalcFrame(targets[t], q_start, v_start);
    const Frame end = CalcFrame(targets[t], q, v);
    for (const ContactProbe& probe : probes_) {
      Vector3d x, x_dot;
      Locate(probe, q, v, &x, &x_dot);
      const double depth = CalcKinematics(targets[t], end, probe, x, x_dot).penetration;
      const double limit = fraction * probe.radius;
      if (!(depth > limit)) continue;
      Locate(probe, q_start, v_start, &x, &x_dot);
      const double depth_start = CalcKinematics(targets[t], start, probe, x, x_dot).penetration;
      if (depth - std::max(depth_start, 0.0) <= limit) continue;
      const std::string where =
          probe.element >= 0 ? fmt::format("element {} at ξ = {:.3f}", probe.element, probe.xi)
                             : fmt::format("point mass {}", probe.point_mass);
      return fmt::format(
          "the inspection sphere of {} sank {:.3g} m into target '{}' in one step (more than {} "
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
                    .xi = probe.xi});
  });
}

}  // namespace ancfnet
