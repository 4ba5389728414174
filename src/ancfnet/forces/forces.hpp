#pragma once
/// @file Assembly of the generalised forces of the equations of motion
///   M q̈ + Q_int(q, q̇) = Q_ext(q, t)
/// and of the iteration matrix c_M M + c_C ∂Q/∂q̇ + c_K ∂Q/∂q, Q = Q_int − Q_ext.

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// Fills ws.internal_force and ws.viscous_force (all coordinates) from the cable elements (in
/// parallel), the spring-damper links, the rigid bodies (gyroscopic terms, attachments) and the
/// clearance joints.
void CalcInternalForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws);

/// Once per step of the midpoint rule, before the corrections below: what they need of the step's
/// start q_start (CalcCableStepStart of every cable element), into ws.element_step_start.
void BeginStepForceCorrections(const Model& model, const VectorXd& q_start, Workspace& ws);
/// For the midpoint rule, after CalcInternalForces at q_m = (q_start + q_end)/2: turns the cable
/// elements' elastic forces into discrete gradients over the step, so that their work equals the
/// change of the strain energy exactly (CalcCableStepForceCorrection; docs/theory.md,
/// "Energy-consistent midpoint rule"). Adds to ws.internal_force.
void AddStepForceCorrections(const Model& model, const VectorXd& q_end, Workspace& ws);
/// matrix += c_K ∂ΔQ/∂q_m of those corrections (their axial part; CalcCableStepForceCorrection),
/// after AssembleIterationMatrix at the midpoint q_m, whose element forces it uses.
void AddStepForceCorrectionJacobians(const Model& model, const VectorXd& q_end,
                                     double stiffness_weight, Workspace& ws, SystemMatrix* matrix);

/// Fills ws.applied_force (point forces, point moments, distributed loads) and ws.external_force
/// = applied + gravity, all scaled by the load factor λ (1 in dynamics).
void CalcExternalForces(const Model& model, const VectorXd& q, double load_factor, Workspace& ws);

/// Weights of the iteration matrix (Drake's discrete_time_integrator: the integrator maps the
/// Newton unknown to (q, v, a) and supplies these).
struct IterationWeights {
  double mass = 0.0;       ///< c_M
  double damping = 0.0;    ///< c_C
  double stiffness = 1.0;  ///< c_K
};

/// matrix = c_M M + c_C ∂Q_int/∂q̇ + c_K (∂Q_int/∂q − ∂Q_ext/∂q), restricted to the unknowns.
/// Also fills ws.internal_force and ws.viscous_force at (q, v) as a by-product.
void AssembleIterationMatrix(const Model& model, const VectorXd& q, const VectorXd& v,
                             const IterationWeights& weights, double load_factor, Workspace& ws,
                             SystemMatrix* matrix);

/// Constant mass matrix over the unknowns of `matrix`.
void AssembleMassMatrix(const Model& model, const Workspace& ws, SystemMatrix* matrix);

}  // namespace ancfnet
