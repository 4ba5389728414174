#include "ancfnet/forces/forces.hpp"

#include <array>

#include "ancfnet/elements/ancf_cable_step_force.hpp"
#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/forces/body_forces.hpp"
#include "ancfnet/forces/clearance_joint_forces.hpp"
#include "ancfnet/forces/link_forces.hpp"
#include "ancfnet/forces/orbital_frame.hpp"
#include "ancfnet/forces/section_lock_forces.hpp"
#include "ancfnet/forces/slope_moment.hpp"

namespace ancfnet {
namespace {

// Below this many elements the parallel region costs more than it saves.
constexpr std::size_t kParallelElements = 64;

template <class Element, int N>
void ScatterAdd(const Element& element, const Eigen::Matrix<double, N, 1>& f, VectorXd* global) {
  for (int i = 0; i < N; ++i) (*global)[element.dofs[i]] += f[i];
}

// The force (and, when `stiffness` is set, the Jacobian) of every element in ws.element_* and
// ws.beam_*: the cable kernel for cable elements, the beam kernel for beam elements (their centre
// lines keep the zeros the Workspace gave them).
void CalcElementForces(const Model& model, const VectorXd& q, const VectorXd& v, bool stiffness,
                       bool damping, Workspace& ws) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
#pragma omp parallel for schedule(static) if (elements.size() >= kParallelElements)
  for (Index e = 0; e < n; ++e) {
    if (elements[e].beam >= 0) continue;
    CalcCableInternalForce(elements[e].parameters, model.Gather(elements[e], q),
                           model.Gather(elements[e], v),
                           {.force = &ws.element_force[e],
                            .viscous_force = &ws.element_viscous_force[e],
                            .stiffness = stiffness ? &ws.element_stiffness[e] : nullptr,
                            .damping = damping ? &ws.element_damping[e] : nullptr});
  }
  const auto& beams = model.beam_elements();
  const Index num_beams = static_cast<Index>(beams.size());
#pragma omp parallel for schedule(static) if (beams.size() >= kParallelElements)
  for (Index b = 0; b < num_beams; ++b)
    CalcBeamInternalForce(beams[b].parameters, model.Gather(beams[b], q), model.Gather(beams[b], v),
                          {.force = &ws.beam_force[b],
                           .viscous_force = &ws.beam_viscous_force[b],
                           .stiffness = stiffness ? &ws.beam_stiffness[b] : nullptr,
                           .damping = damping ? &ws.beam_damping[b] : nullptr});
}

// The blocks a point moment acts on, each with its weight: the slope r' of a cable node; r_x,
// r_y and r_z of a beam node, each with ½, so that a rigid rotation δθ of an orthonormal frame
// does the work M·δθ (docs/theory.md, "Point moment on a beam node").
// Unused entries have weight 0 (no allocation in the time loop).
struct MomentBlock {
  Index dof = 0;
  double weight = 0.0;
};
std::array<MomentBlock, 3> MomentBlocks(const Model& model, Index node) {
  const CableNode& n = model.nodes()[node];
  if (n.section_dof < 0) return {{{n.slope_dof, 1.0}}};
  return {{{n.slope_dof, 0.5}, {n.section_dof, 0.5}, {n.section_dof + 3, 0.5}}};
}

// scale · m I on the diagonal block of every point mass.
void AddPointMassMatrix(const Model& model, double scale, SystemMatrix* matrix) {
  const auto& points = model.point_masses();
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix->AddPointMassBlock(static_cast<Index>(i), Matrix3d::Identity(), scale * points[i].mass);
}

// ws.element_step_correction (and with `jacobian` ws.element_step_jacobian) of every cable
// element over the step from ws.element_step_start to q_end, from the elastic forces in
// ws.element_force.
void CalcStepForceCorrections(const Model& model, const VectorXd& q_end, bool jacobian,
                              Workspace& ws) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
#pragma omp parallel for schedule(static) if (elements.size() >= kParallelElements)
  for (Index e = 0; e < n; ++e) {
    if (elements[e].beam >= 0) continue;
    ws.element_step_correction[e] = CalcCableStepForceCorrection(
        elements[e].parameters, ws.element_step_start[e], model.Gather(elements[e], q_end),
        ws.element_force[e] - ws.element_viscous_force[e],
        jacobian ? &ws.element_step_jacobian[e] : nullptr);
  }
}

}  // namespace

void CalcInternalForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws) {
  CalcElementForces(model, q, v, /*stiffness=*/false, /*damping=*/false, ws);
  const auto& elements = model.elements();
  ws.internal_force.setZero();
  ws.viscous_force.setZero();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    ScatterAdd(elements[e], ws.element_force[e], &ws.internal_force);
    ScatterAdd(elements[e], ws.element_viscous_force[e], &ws.viscous_force);
  }
  for (std::size_t b = 0; b < model.beam_elements().size(); ++b) {
    ScatterAdd(model.beam_elements()[b], ws.beam_force[b], &ws.internal_force);
    ScatterAdd(model.beam_elements()[b], ws.beam_viscous_force[b], &ws.viscous_force);
  }
  AddLinkForces(model, q, v, ws);
  AddSectionLockForces(model, q, ws);
  AddBodyForces(model, q, v, ws);
  AddClearanceJointForces(model, q, v, ws);
  AddOrbitalFrameForces(model, q, v, ws);
}

void BeginStepForceCorrections(const Model& model, const VectorXd& q_start, Workspace& ws) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
#pragma omp parallel for schedule(static) if (elements.size() >= kParallelElements)
  for (Index e = 0; e < n; ++e)
    if (elements[e].beam < 0)
      ws.element_step_start[e] =
          CalcCableStepStart(elements[e].parameters, model.Gather(elements[e], q_start));
}

void AddStepForceCorrections(const Model& model, const VectorXd& q_end, Workspace& ws) {
  CalcStepForceCorrections(model, q_end, false, ws);
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].beam < 0)
      ScatterAdd(elements[e], ws.element_step_correction[e], &ws.internal_force);
}

void AddStepForceCorrectionJacobians(const Model& model, const VectorXd& q_end,
                                     double stiffness_weight, Workspace& ws, SystemMatrix* matrix) {
  CalcStepForceCorrections(model, q_end, true, ws);
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e)
    if (elements[e].beam < 0)
      matrix->AddElementBlock(static_cast<Index>(e), ws.element_step_jacobian[e],
                              stiffness_weight);
}

void CalcExternalForces(const Model& model, const VectorXd& q, double load_factor, Workspace& ws) {
  ws.applied_force = ws.distributed_force;
  for (const PointForce& load : model.point_forces()) {
    const CableElement& element = model.elements()[load.point.element];
    const HermiteShape shape = CalcHermiteShape(load.point.xi, element.parameters.length);
    ScatterAdd(element, DistributeForce(shape.s, load.force), &ws.applied_force);
  }
  for (const PointMoment& load : model.point_moments())
    for (const auto [dof, weight] : MomentBlocks(model, load.node))
      if (weight != 0.0)
        ws.applied_force.segment<3>(dof) +=
          weight * CalcSlopeMomentForce(load.moment, q.segment<3>(dof));
  ws.applied_force *= load_factor;
  ws.external_force = ws.applied_force + load_factor * ws.gravity_force;
}

void AssembleIterationMatrix(const Model& model, const VectorXd& q, const VectorXd& v,
                             const IterationWeights& weights, double load_factor, Workspace& ws,
                             SystemMatrix* matrix) {
  const auto& elements = model.elements();
  const Index n = static_cast<Index>(elements.size());
  const bool need_damping = weights.damping != 0.0;
  CalcElementForces(model, q, v, /*stiffness=*/true, need_damping, ws);
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
  for (std::size_t b = 0; b < model.beam_elements().size(); ++b) {
    const Index beam = static_cast<Index>(b);
    ScatterAdd(model.beam_elements()[b], ws.beam_force[b], &ws.internal_force);
    ScatterAdd(model.beam_elements()[b], ws.beam_viscous_force[b], &ws.viscous_force);
    matrix->AddBeamElementBlock(beam, ws.beam_stiffness[b], weights.stiffness);
    if (weights.mass != 0.0)
      matrix->AddBeamElementBlock(beam, ws.beam_rotary_mass[b], weights.mass);
    if (need_damping) matrix->AddBeamElementBlock(beam, ws.beam_damping[b], weights.damping);
  }
  AddLinkForces(model, q, v, ws);
  AddLinkJacobians(model, q, v, weights, ws, matrix);
  AddSectionLockForces(model, q, ws);
  AddSectionLockJacobians(model, q, weights.stiffness, matrix);
  AddBodyForces(model, q, v, ws);
  AddBodyJacobians(model, q, v, weights, ws, matrix);
  AddClearanceJointForces(model, q, v, ws);
  AddClearanceJointJacobians(model, q, v, weights, ws, matrix);
  AddOrbitalFrameForces(model, q, v, ws);
  AddOrbitalFrameJacobians(model, q, v, ws, weights.stiffness, weights.damping, matrix);
  if (weights.mass != 0.0) {
    AddPointMassMatrix(model, weights.mass, matrix);
    AddBodyMassMatrix(model, weights.mass, matrix);
  }
  // Point moments depend on the slope: −c_K λ ∂Q_ext/∂q.
  for (const PointMoment& load : model.point_moments())
    for (const auto [dof, weight] : MomentBlocks(model, load.node))
      if (weight != 0.0)
        matrix->AddBlock3(dof, dof, CalcSlopeMomentJacobian(load.moment, q.segment<3>(dof)),
                        -weight * weights.stiffness * load_factor);
}

void AssembleMassMatrix(const Model& model, const Workspace& ws, SystemMatrix* matrix) {
  matrix->SetZero();
  for (std::size_t e = 0; e < model.elements().size(); ++e)
    matrix->AddElementBlock(static_cast<Index>(e), ws.element_mass[e]);
  for (std::size_t b = 0; b < model.beam_elements().size(); ++b)
    matrix->AddBeamElementBlock(static_cast<Index>(b), ws.beam_rotary_mass[b]);
  AddPointMassMatrix(model, 1.0, matrix);
  AddBodyMassMatrix(model, 1.0, matrix);
}

}  // namespace ancfnet
