#include "ancfnet/forces/target_contact.hpp"

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
    : model_(model), probes_(MakeContactProbes(model)) {}

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

TargetContact::PairForce TargetContact::CalcPairForce(const ContactTarget& target,
                                              const ContactProbe& probe, const Vector3d& x,
                                              const Vector3d& x_dot, double approach_speed,
                                              bool with_jacobian) const {
  const Gap gap = CalcGap(target, x);
  // history > 0: the impact speed frozen at first touch; ≤ 0: apart at the last accepted
  // state, closing at −history (a constant through this step's Newton iterations).
  const ContactKinematics kinematics{.penetration = probe.radius - gap.distance,
                                     .normal = gap.normal,
                                     .normal_derivative = gap.hessian,
                                     .velocity = x_dot};
  const ContactSpec& spec = model_.contact();
  PairForce r;
  static_cast<ContactPairForce&>(r) =
      CalcContactPairForce(spec.normal, spec.friction, kinematics, approach_speed, with_jacobian);
  r.surface_point = x - gap.distance * gap.normal;
  r.normal = gap.normal;
  return r;
}

template <class Visit>
void TargetContact::ForEachTouchingPair(const VectorXd& q, const VectorXd& v,
                                        const std::vector<double>& history, bool with_jacobian,
                                        Visit&& visit) const {
  const auto& targets = model_.contact().targets;
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Vector3d x, x_dot;
    Locate(probes_[p], q, v, &x, &x_dot);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      PairForce f = CalcPairForce(targets[t], probes_[p], x, x_dot, history[p * targets.size() + t],
                                  with_jacobian);
      if (!f.touching) continue;
      f.target = static_cast<Index>(t);
      visit(probes_[p], f);
    }
  }
}

void TargetContact::AddForces(const VectorXd& q, const VectorXd& v,
                              const std::vector<double>& history, Workspace& ws) const {
  ws.contact_energy = 0.0;
  ForEachTouchingPair(q, v, history, false,
                      [&](const ContactProbe& probe, const ContactPairForce& f) {
                        ws.contact_energy += f.energy;
                        if (probe.element < 0) {
                          const Index dof = model_.point_masses()[probe.point_mass].dof;
                          ws.internal_force.segment<3>(dof) -= f.force;
                          ws.viscous_force.segment<3>(dof) -= f.dissipative;
                          return;
                        }
                        const CableElement& element = model_.elements()[probe.element];
                        for (int k = 0; k < 4; ++k) {
                          const Index dof = element.dofs[3 * k];
                          ws.internal_force.segment<3>(dof) -= probe.shape[k] * f.force;
                          ws.viscous_force.segment<3>(dof) -= probe.shape[k] * f.dissipative;
                        }
                      });
}

void TargetContact::AddJacobian(const VectorXd& q, const VectorXd& v,
                                const std::vector<double>& history, const IterationWeights& weights,
                                SystemMatrix* matrix) const {
  ForEachTouchingPair(
      q, v, history, true, [&](const ContactProbe& probe, const ContactPairForce& f) {
        // Q = −Sᵀ f: ∂Q/∂e = −Sᵀ (∂f/∂x) S.
        const Matrix3d block = -(weights.stiffness * f.dforce_dx + weights.damping * f.dforce_dv);
        if (probe.element < 0) {
          matrix->AddPointMassBlock(probe.point_mass, block);
          return;
        }
        Matrix12d element_block;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            element_block.block<3, 3>(3 * i, 3 * j) = probe.shape[i] * probe.shape[j] * block;
        matrix->AddElementBlock(probe.element, element_block);
      });
}

void TargetContact::UpdateHistory(const VectorXd& q, const VectorXd& v,
                                  std::vector<double>* history) const {
  const auto& targets = model_.contact().targets;
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Vector3d x, x_dot;
    Locate(probes_[p], q, v, &x, &x_dot);
    for (std::size_t t = 0; t < targets.size(); ++t) {
      double& stored = (*history)[p * targets.size() + t];
      const Gap gap = CalcGap(targets[t], x);
      const double closing = std::max(-gap.normal.dot(x_dot), 0.0);
      if (!(probes_[p].radius - gap.distance > 0.0)) {
        stored = -closing;  // apart: remember how fast it closes in
      } else if (stored <= 0.0) {
        // Just touched: its impact speed is the closing speed before the touch.
        stored = std::max(std::max(-stored, closing), model_.contact().normal.min_approach_speed);
      }
    }
  }
}

TargetContact::Summary TargetContact::Summarize(const VectorXd& q, const VectorXd& v,
                                                const std::vector<double>& history) const {
  Summary s;
  ForEachTouchingPair(q, v, history, false, [&](const ContactProbe&, const ContactPairForce& f) {
    ++s.active;
    s.normal_force += f.normal_force;
    s.max_penetration = std::max(s.max_penetration, f.penetration);
  });
  return s;
}

void TargetContact::CollectContacts(const VectorXd& q, const VectorXd& v,
                                    const std::vector<double>& history,
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
