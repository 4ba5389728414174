#pragma once
/// @file Assembly of the spring-damper links (forces/spring_damper.hpp) between located points:
/// a link whose second point feels f₂ adds −w_b f₂ to Q_int on the second point's blocks and
/// +w_b f₂ on the first's (Q_int is on the left of M q̈ + Q_int = Q_ext).

#include "ancfnet/forces/forces.hpp"
#include "ancfnet/forces/spring_damper.hpp"

namespace ancfnet {

/// Adds every intact link's force to ws.internal_force and its damping part to ws.viscous_force
/// (links marked in ws.link_broken are skipped here and below).
void AddLinkForces(const Model& model, const VectorXd& q, const VectorXd& v, Workspace& ws);

/// Adds c_K ∂Q_int/∂q + c_C ∂Q_int/∂q̇ of every link to `matrix`: block (i, j) of a link is
/// −σ_i σ_j w_i w_j (c_K ∂f₂/∂d + c_C ∂f₂/∂ḋ), σ = +1 on the second point's blocks, −1 on the
/// first's, d = r₂ − r₁.
void AddLinkJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                      const IterationWeights& weights, const Workspace& ws, SystemMatrix* matrix);

/// Energy stored in one link (J), broken or not.
double CalcLinkEnergy(const SpringDamperLink& link, const VectorXd& q);
/// Energy stored in the intact links (J).
double CalcLinkEnergy(const Model& model, const Workspace& ws, const VectorXd& q);

/// Force, tension and energy of one link at (q, v), as if intact.
SpringDamperResult CalcLinkState(const SpringDamperLink& link, const VectorXd& q,
                                 const VectorXd& v);

}  // namespace ancfnet
