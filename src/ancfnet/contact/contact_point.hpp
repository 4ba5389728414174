#pragma once
/// @file ContactPoint: a plain record of one active contact, the common currency of every contact
/// kind (cable or point mass against a rigid target, self-contact) for outputs: probes, VTK
/// frames, tests. Made at output times, never in the time loop.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// One touching (probe, target) pair at a state. The probe is an inspection sphere of a cable
/// element at ξ, or a point mass. Forces act on the probe; the target feels −force_W at point_W.
struct ContactPoint {
  Vector3d point_W = Vector3d::Zero();    ///< closest point on the target's surface (m)
  Vector3d normal_W = Vector3d::UnitZ();  ///< unit normal, from the target towards the probe
  double penetration = 0.0;               ///< δ = r − d > 0 (m)
  double normal_force = 0.0;              ///< F(δ, δ̇) along normal_W, damping included (N)
  Vector3d friction_force_W = Vector3d::Zero();  ///< tangential friction on the probe (N)
  Vector3d force_W = Vector3d::Zero();           ///< total on the probe: F n + friction (N)
  Index target = -1;      ///< index into ContactSpec::targets, or −1 for self-contact
  Index element = -1;     ///< cable element of the probe, or −1 for a point mass
  Index point_mass = -1;  ///< point mass of the probe, or −1
  double xi = 0.0;  ///< ξ ∈ [0, 1] of the probe (a capsule: its deepest point) on its element
};

}  // namespace ancfnet
