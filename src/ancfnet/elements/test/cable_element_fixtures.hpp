#pragma once
/// @file Test fixtures of the cable element's tests: parameters of a 0.25 m thread and the nodal
/// coordinates of a straight, uniformly stretched element.

#include "ancfnet/elements/ancf_cable.hpp"

namespace ancfnet::test {

/// L = 0.25 m, EA = 2·10⁴ N, EI = 3 N m², ρA = 0.78 kg/m.
inline CableElementParameters MakeCableTestParameters() {
  CableElementParameters p;
  p.length = 0.25;
  p.axial_stiffness = 2.0e4;
  p.bending_stiffness = 3.0;
  p.mass_per_length = 0.78;
  return p;
}

/// Nodal coordinates of a straight element from x0 along `dir` (unit), stretched by `stretch`.
inline Vector12d StraightElement(const Vector3d& x0, const Vector3d& dir, double length,
                                 double stretch) {
  Vector12d e;
  e << x0, stretch * dir, x0 + stretch * length * dir, stretch * dir;
  return e;
}

}  // namespace ancfnet::test
