#pragma once
/// @file Relative motion near a target on a circular orbit, written in the target's local
/// orbital (Hill) frame: x radial (away from the Earth), y along-track, z orbit normal. With mean
/// motion n the Clohessy–Wiltshire (1960) equations of a point are
///   ẍ − 2n ẏ − 3n² x = f_x/m,   ÿ + 2n ẋ = f_y/m,   z̈ + n² z = f_z/m,
/// i.e. an extra acceleration K r + G ṙ with K = diag(3n², 0, −n²) and G = [0 2n 0; −2n 0 0;
/// 0 0 0]. The field is linear in r and ṙ, so on a cable element, where r = S e, its generalised
/// force is exactly M_e (I₄ ⊗ K) e + M_e (I₄ ⊗ G) ė (the same for slopes as for positions), and
/// on a point mass m (K r + G ṙ). On a beam element, whose material points are
/// r + y d₂ + z d₃, it is likewise its full mass matrix times (I₈ ⊗ K) e + (I₈ ⊗ G) ė: the centre
/// line's part, as on a cable, plus the rotary part (Workspace::beam_rotary_mass) on d₂, d₃,
/// which holds the gravity-gradient torque and the Coriolis forces of the sections' spin
/// (docs/theory.md, "Beams in an orbital frame"). On a free rigid body, the same field on its
/// centre of mass and the gravity-gradient and frame-rate terms of its rotation
/// (forces/orbital_frame_body.hpp).
///
/// Energy: the Coriolis part does no work (M ⊗ G is skew), and the tidal part derives from the
/// potential V = −½ qᵀ M (I ⊗ K) q, which the energy account adds to the gravity column (the
/// Jacobi integral of the CW equations).

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/workspace.hpp"

namespace ancfnet {

/// K = diag(3n², 0, −n²) (1/s²).
Matrix3d CalcHillStiffness(double mean_motion);
/// G = [0 2n 0; −2n 0 0; 0 0 0] (1/s).
Matrix3d CalcHillGyroscopic(double mean_motion);

/// Subtracts the frame's generalised forces from ws.internal_force (they act on the left as
/// −M (K̃ q + G̃ v)). Nothing when the model has no orbital frame.
void AddOrbitalFrameForces(const Model& model, const VectorXd& q, const VectorXd& v,
                           Workspace& ws);

/// Adds −c_K M (I ⊗ K) − c_C M (I ⊗ G) to the iteration matrix, and the free bodies' terms at
/// (q, v) with the reference rotations in ws.
void AddOrbitalFrameJacobians(const Model& model, const VectorXd& q, const VectorXd& v,
                              const Workspace& ws, double stiffness_weight, double damping_weight,
                              SystemMatrix* matrix);

/// V = −½ qᵀ M (I ⊗ K) q plus the free bodies' potentials (forces/orbital_frame_body.hpp) (J).
double CalcOrbitalPotential(const Model& model, const Workspace& ws, const VectorXd& q);

}  // namespace ancfnet
