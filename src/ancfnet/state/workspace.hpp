#pragma once
/// @file Workspace: scratch storage sized once for a model, so that the time loop allocates
/// nothing. Each field says which stage fills it.

#include <vector>

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/ancf_cable_step_force.hpp"
#include "ancfnet/elements/beam_shape.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

class Model;

struct Workspace {
  explicit Workspace(const Model& model);

  // Constant, filled by the constructor.
  std::vector<Matrix12d> element_mass;  ///< consistent mass matrix of each element
  /// Rotary-inertia part of each beam element's consistent mass, ∫ (ρI_z S₂ᵀS₂ + ρI_y S₃ᵀS₃) dx;
  /// its translational part ∫ ρA SᵣᵀSᵣ dx is element_mass of its centre line (the same Hermite).
  std::vector<Matrix24d> beam_rotary_mass;
  VectorXd gravity_force;      ///< ∫ ρA Sᵀ g dx, m g of point masses and free bodies (N)
  VectorXd distributed_force;  ///< ∫ Sᵀ w dx of the distributed loads (N)

  // Per element, filled by CalcInternalForces / AssembleIterationMatrix.
  std::vector<Vector12d> element_force;
  std::vector<Vector12d> element_viscous_force;
  /// BeginStepForceCorrections: what the step-force corrections need of the step's start.
  std::vector<CableStepStart> element_step_start;
  /// AddStepForceCorrections: what turns element_force into the discrete gradient over a step.
  std::vector<Vector12d> element_step_correction;
  std::vector<Matrix12d> element_step_jacobian;  ///< its ∂/∂q_m (AddStepForceCorrectionJacobians)
  std::vector<Matrix12d> element_stiffness;
  std::vector<Matrix12d> element_damping;
  // Per beam element, filled by CalcInternalForces / AssembleIterationMatrix; the entries of its
  // centre line above stay zero.
  std::vector<Vector24d> beam_force;
  std::vector<Vector24d> beam_viscous_force;
  std::vector<Matrix24d> beam_stiffness;
  std::vector<Matrix24d> beam_damping;

  // Copied from State::link_broken by the integrators before they evaluate forces; the force,
  // Jacobian and energy of a broken link are skipped.
  std::vector<char> link_broken;
  // Copied from State::body_rotation by the integrators (after every rebase): the reference
  // orientations R_ref the body forces are evaluated with.
  std::vector<Matrix3d> body_rotation;
  /// Elastic energy stored in the contacts (J): set by the contact forces (TargetContact).
  double contact_energy = 0.0;
  // Copied from State::joint_history by the integrators at the start of a step: the impact
  // speeds the clearance joints' forces are evaluated with.
  std::vector<ContactPairHistory> joint_history;
  // Set by SystemForces::Calc and AssembleIterationMatrix: the step size h (s) over which the
  // clearance joints' LuGre bristles are advanced from joint_history; 0: the forces at the state.
  double joint_step = 0.0;

  // Global coordinate vectors (all coordinates, fixed included).
  VectorXd internal_force;  ///< Q_int(q, v): CalcInternalForces
  VectorXd viscous_force;   ///< its Kelvin–Voigt part: CalcInternalForces
  VectorXd applied_force;   ///< loads other than gravity at the load factor: CalcExternalForces
  VectorXd external_force;  ///< applied_force + λ · gravity_force: CalcExternalForces
  /// The force the prescribed motion applies to its coordinates, (M a + Q_int − Q_ext) there and
  /// 0 elsewhere, at the last accepted state: generalised-α (ImplicitStepCore::CalcDriveForce).
  /// Its work is part of the energy account's W.
  VectorXd drive_force;
};

}  // namespace ancfnet
