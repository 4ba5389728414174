#include "ancfnet/forces/orbital_frame.hpp"

#include "ancfnet/forces/orbital_frame_body.hpp"

namespace ancfnet {
namespace {

// (I ⊗ A) x for a vector x of 3-blocks (12: a cable element, 24: a beam element).
template <int kSize>
Eigen::Matrix<double, kSize, 1> ApplyToBlocks(const Matrix3d& a,
                                              const Eigen::Matrix<double, kSize, 1>& x) {
  Eigen::Matrix<double, kSize, 1> y;
  for (int b = 0; b < kSize / 3; ++b)
    y.template segment<3>(3 * b) = a * x.template segment<3>(3 * b);
  return y;
}

// M (I ⊗ A).
template <int kSize>
Eigen::Matrix<double, kSize, kSize> MassTimesBlocks(const Eigen::Matrix<double, kSize, kSize>& mass,
                                                    const Matrix3d& a) {
  Eigen::Matrix<double, kSize, kSize> m;
  for (int b = 0; b < kSize / 3; ++b)
    m.template middleCols<3>(3 * b) = mass.template middleCols<3>(3 * b) * a;
  return m;
}

}  // namespace

Matrix3d CalcHillStiffness(double n) { return Vector3d(3.0 * n * n, 0.0, -n * n).asDiagonal(); }

Matrix3d CalcHillGyroscopic(double n) {
  Matrix3d g = Matrix3d::Zero();
  g(0, 1) = 2.0 * n;
  g(1, 0) = -2.0 * n;
  return g;
}

void AddOrbitalFrameForces(const Model& model, const VectorXd& q, const VectorXd& v,
                           Workspace& ws) {
  if (!model.orbital_frame()) return;
  const Matrix3d k = CalcHillStiffness(*model.orbital_frame());
  const Matrix3d g = CalcHillGyroscopic(*model.orbital_frame());
  // −M (K̃ e + G̃ ė) of one element with mass matrix `mass`.
  const auto subtract_field = [&](const auto& element, const auto& mass) {
    const auto accel =
        (ApplyToBlocks(k, model.Gather(element, q)) + ApplyToBlocks(g, model.Gather(element, v)))
            .eval();
    const auto force = (mass * accel).eval();
    for (Index i = 0; i < force.size(); ++i) ws.internal_force[element.dofs[i]] -= force[i];
  };
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) subtract_field(elements[e], ws.element_mass[e]);
  // The sections' rotary inertia: the field on y d₂ + z d₃ (docs/theory.md, "Beams in an
  // orbital frame").
  const auto& beams = model.beam_elements();
  for (std::size_t b = 0; b < beams.size(); ++b) subtract_field(beams[b], ws.beam_rotary_mass[b]);
  for (const PointMass& point : model.point_masses())
    ws.internal_force.segment<3>(point.dof) -=
        point.mass * (k * q.segment<3>(point.dof) + g * v.segment<3>(point.dof));
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].motion != BodyMotion::kFree) continue;
    const HillBodyTerms t = CalcHillBodyTerms(
        bodies[b].mass, bodies[b].inertia, CalcBodyPose(bodies[b], q, ws.body_rotation[b]),
        CalcBodyVelocity(bodies[b], v), *model.orbital_frame());
    ws.internal_force.segment<3>(bodies[b].position_dof()) += t.force;
    ws.internal_force.segment<3>(bodies[b].rotation_dof()) += t.moment;
  }
}

void AddOrbitalFrameJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                              const Workspace& ws, double stiffness_weight, double damping_weight,
                              SystemMatrix* matrix) {
  if (!model.orbital_frame()) return;
  const Matrix3d k = CalcHillStiffness(*model.orbital_frame());
  const Matrix3d g = CalcHillGyroscopic(*model.orbital_frame());
  const Matrix3d field = stiffness_weight * k + damping_weight * g;
  for (std::size_t e = 0; e < model.elements().size(); ++e)
    matrix->AddElementBlock(static_cast<Index>(e), MassTimesBlocks(ws.element_mass[e], field),
                            -1.0);
  for (std::size_t b = 0; b < model.beam_elements().size(); ++b)
    matrix->AddBeamElementBlock(static_cast<Index>(b),
                                MassTimesBlocks(ws.beam_rotary_mass[b], field), -1.0);
  const auto& points = model.point_masses();
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix->AddPointMassBlock(static_cast<Index>(i), field, -points[i].mass);
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].motion != BodyMotion::kFree) continue;
    const HillBodyTerms t = CalcHillBodyTerms(
        bodies[b].mass, bodies[b].inertia, CalcBodyPose(bodies[b], q, ws.body_rotation[b]),
        CalcBodyVelocity(bodies[b], v), *model.orbital_frame());
    const Index body = static_cast<Index>(b);
    matrix->AddBodyBlock(body, 0, 0, field, -bodies[b].mass);
    matrix->AddBodyBlock(body, 1, 1,
                         stiffness_weight * t.moment_rotation + damping_weight * t.moment_rate);
  }
}

double CalcOrbitalPotential(const Model& model, const Workspace& ws, const VectorXd& q) {
  if (!model.orbital_frame()) return 0.0;
  const Matrix3d k = CalcHillStiffness(*model.orbital_frame());
  double potential = 0.0;
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Vector12d x = model.Gather(elements[e], q);
    potential -= 0.5 * x.dot(ws.element_mass[e] * ApplyToBlocks(k, x));
  }
  const auto& beams = model.beam_elements();
  for (std::size_t b = 0; b < beams.size(); ++b) {
    const Vector24d x = model.Gather(beams[b], q);
    potential -= 0.5 * x.dot(ws.beam_rotary_mass[b] * ApplyToBlocks(k, x));
  }
  for (const PointMass& point : model.point_masses())
    potential -= 0.5 * point.mass * q.segment<3>(point.dof).dot(k * q.segment<3>(point.dof));
  const auto& bodies = model.rigid_bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].motion == BodyMotion::kFree)
      potential += CalcHillBodyPotential(bodies[b].mass, bodies[b].inertia,
                                         CalcBodyPose(bodies[b], q, ws.body_rotation[b]),
                                         *model.orbital_frame());
  return potential;
}

}  // namespace ancfnet
