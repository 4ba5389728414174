#include "ancfnet/forces/forces.hpp"

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/forces/body_forces.hpp"
#include "ancfnet/forces/link_forces.hpp"
#include "ancfnet/forces/orbital_frame.hpp"
#include "ancfnet/forces/slope_moment.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"

namespace ancfnet {
namespace {

// Below this many elements the parallel region costs more than it saves.
constexpr std::size_t kParallelElements = 64;

void ScatterAdd(const CableElement& element, const Vector12d& f, VectorXd* global) {
  for (int i = 0; i < kCableElementDofs; ++i) (*global)[element.dofs[i]] += f[i];
}

// scale · m I on the diagonal block of every point mass.
void AddPointMassMatrix(const Model& model, double scale, SystemMatrix* matrix) {
  const auto& points = model.point_masses();
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix->AddPointMassBlock(static_cast<Index>(i), Matrix3d::Identity(), scale * points[i].mass);
}

}  // namespace

void CalcInternalForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
#pragma omp parallel for schedule(static) if (elements.size() >= kParallelElements)
  for (Index e = 0; e < n; ++e) {
    CalcCableInternalForce(
        elements[e].parameters, model.Gather(elements[e], q), model.Gather(elements[e], v),
        {.force = &ws.element_force[e], .viscous_force = &ws.element_viscous_force[e]});
  }
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  for (Index e = 0; e < n; ++e) {
    ScatterAdd(elements[e], ws.element_force[e], &ws.internal_force);
    ScatterAdd(elements[e], ws.element_viscous_force[e], &ws.viscous_force);
  }
  AddLinkForces(model, q, v, ws);
  AddBodyForces(model, q, v, ws);
  AddClearanceJointForces(model, q, v, ws);
  AddOrbitalFrameForces(model, q, v, ws);
}

void CalcExternalForces(const Model& model, const VectorXd& q, double load_factor, Workspace& ws) {
  ws.applied_force = ws.distributed_force;
  for (const PointForce& load : model.point_forces()) {
    const CableElement& element = model.elements()[load.point.element];
    const HermiteShape shape = CalcHermiteShape(load.point.xi, element.parameters.length);
    ScatterAdd(element, DistributeForce(shape.s, load.force), &ws.applied_force);
  }
  for (const PointMoment& load : model.point_moments()) {
    const Index slope = model.NodeSlopeDof(load.node);
    ws.applied_force.segment<3>(slope) += CalcSlopeMomentForce(load.moment, q.segment<3>(slope));
  }
  ws.applied_force *= load_factor;
  ws.external_force = ws.applied_force + load_factor * ws.gravity_force;
}

void AssembleIterationMatrix(const Model& model, const VectorXd& q, const VectorXd& v,
                             const IterationWeights& weights, double load_factor, Workspace& ws,
                             SystemMatrix* matrix) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
  const bool need_damping = weights.damping != 0.0;
#pragma omp parallel for schedule(static) if (elements.size() >= kParallelElements)
  for (Index e = 0; e < n; ++e) {
    CalcCableInternalForce(elements[e].parameters, model.Gather(elements[e], q),
                           model.Gather(elements[e], v),
                           {.force = &ws.element_force[e],
                            .viscous_force = &ws.element_viscous_force[e],
                            .stiffness = &ws.element_stiffness[e],
                            .damping = need_damping ? &ws.element_damping[e] : nullptr});
  }
  matrix->SetZero();
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  for (Index e = 0; e < n; ++e) {
    ScatterAdd(elements[e], ws.element_force[e], &ws.internal_force);
    ScatterAdd(elements[e], ws.element_viscous_force[e], &ws.viscous_force);
    matrix->AddElementBlock(e, ws.element_stiffness[e], weights.stiffness);
    if (weights.mass != 0.0) matrix->AddElementBlock(e, ws.element_mass[e], weights.mass);
    if (need_damping) matrix->AddElementBlock(e, ws.element_damping[e], weights.damping);
  }
  AddLinkForces(model, q, v, ws);
  AddLinkJacobians(model, q, v, weights, ws, matrix);
  AddBodyForces(model, q, v, ws);
  AddBodyJacobians(model, q, v, weights, ws, matrix);
  AddClearanceJointForces(model, q, v, ws);
  AddClearanceJointJacobians(model, q, v, weights, ws, matrix);
  AddOrbitalFrameForces(model, q, v, ws);
  AddOrbitalFrameJacobians(model, ws, weights.stiffness, weights.damping, matrix);
  if (weights.mass != 0.0) {
    AddPointMassMatrix(model, weights.mass, matrix);
    AddBodyMassMatrix(model, weights.mass, matrix);
  }
  // Point moments depend on the slope: −c_K λ ∂Q_ext/∂q.
  for (const PointMoment& load : model.point_moments()) {
    const Index slope = model.NodeSlopeDof(load.node);
    matrix->AddBlock3(slope, slope, CalcSlopeMomentJacobian(load.moment, q.segment<3>(slope)),
                      -weights.stiffness * load_factor);
  }
}

void AssembleMassMatrix(const Model& model, const Workspace& ws, SystemMatrix* matrix) {
  matrix->SetZero();
  for (std::size_t e = 0; e < model.elements().size(); ++e)
    matrix->AddElementBlock(static_cast<Index>(e), ws.element_mass[e]);
  AddPointMassMatrix(model, 1.0, matrix);
  AddBodyMassMatrix(model, 1.0, matrix);
}

}  // namespace ancfnet
