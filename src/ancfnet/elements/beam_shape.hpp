#pragma once
/// @file Interpolation of the 24-coordinate ANCF beam element (Shabana & Yakoub 2001; Yakoub &
/// Shabana 2001): e = [r_A, r_x,A, r_y,A, r_z,A, r_B, r_x,B, r_y,B, r_z,B] and
///   r(x, y, z) = Σ Hᵢ(x) [r_A, r_x,A, r_B, r_x,B]ᵢ + y d₂(x) + z d₃(x),
///   d₂ = (1 − ξ) r_y,A + ξ r_y,B,  d₃ = (1 − ξ) r_z,A + ξ r_z,B,  ξ = x/L,
/// cubic Hermite Hᵢ along the axis and linear across (the "3243" element). The first six
/// coordinates of a node are those of a cable node (elements/hermite_shape.hpp).

#include "ancfnet/common/types.hpp"
#include "ancfnet/elements/beam_strain_jet.hpp"
#include "ancfnet/elements/hermite_shape.hpp"

namespace ancfnet {

/// Coordinates of one beam node (r, r_x, r_y, r_z) and of one beam element.
inline constexpr int kBeamNodeDofs = 12;
inline constexpr int kBeamElementDofs = 24;
using Vector24d = Eigen::Matrix<double, kBeamElementDofs, 1>;
using Matrix24d = Eigen::Matrix<double, kBeamElementDofs, kBeamElementDofs>;

/// The 3-vector blocks of e: r_A, r_x,A, r_y,A, r_z,A, r_B, r_x,B, r_y,B, r_z,B.
inline constexpr int kBeamElementBlocks = 8;
using BeamBlockMatrix = Eigen::Matrix<double, 6, kBeamElementBlocks>;

/// The linear map u = (b ⊗ I₃) e from the element coordinates to the local quantities
/// u = [r', r'', d₂, d₃, d₂', d₃'] (elements/beam_strain_jet.hpp) at ξ ∈ [0, 1], together with the
/// position weights r = Σ position_j e_j.
struct BeamLocalMap {
  BeamBlockMatrix b = BeamBlockMatrix::Zero();
  Eigen::Matrix<double, kBeamElementBlocks, 1> position =
      Eigen::Matrix<double, kBeamElementBlocks, 1>::Zero();
};

/// The map at ξ for an element of reference length L > 0 (m).
inline BeamLocalMap MakeBeamLocalMap(double xi, double length) {
  const HermiteShape h = CalcHermiteShape(xi, length);
  constexpr int kAxis[4] = {0, 1, 4, 5};  // blocks r_A, r_x,A, r_B, r_x,B
  BeamLocalMap m;
  for (int i = 0; i < 4; ++i) {
    m.b(kSlope, kAxis[i]) = h.ds[i];
    m.b(kCurvatureVector, kAxis[i]) = h.dds[i];
    m.position[kAxis[i]] = h.s[i];
  }
  for (int d = 0; d < 2; ++d) {  // d₂ from blocks 2 and 6, d₃ from blocks 3 and 7
    m.b(kD2 + d, 2 + d) = 1.0 - xi;
    m.b(kD2 + d, 6 + d) = xi;
    m.b(kD2x + d, 2 + d) = -1.0 / length;
    m.b(kD2x + d, 6 + d) = 1.0 / length;
  }
  return m;
}

/// u = (b ⊗ I₃) e.
inline BeamLocalVector MapToLocal(const BeamLocalMap& m, const Vector24d& e) {
  BeamLocalVector u;
  Eigen::Map<Eigen::Matrix<double, 3, 6>>(u.data()) =
      Eigen::Map<const Eigen::Matrix<double, 3, kBeamElementBlocks>>(e.data()) * m.b.transpose();
  return u;
}

/// (b ⊗ I₃)ᵀ g: a gradient with respect to u as one with respect to e.
inline Vector24d MapToNodal(const BeamLocalMap& m, const BeamLocalVector& g) {
  Vector24d q;
  Eigen::Map<Eigen::Matrix<double, 3, kBeamElementBlocks>>(q.data()) =
      Eigen::Map<const Eigen::Matrix<double, 3, 6>>(g.data()) * m.b;
  return q;
}

/// k += (b ⊗ I₃)ᵀ h (b ⊗ I₃): a Hessian with respect to u as one with respect to e.
inline void AddMappedHessian(const BeamLocalMap& m, const BeamLocalMatrix& h, Matrix24d& k) {
  for (int i = 0; i < 6; ++i)
    for (int n = 0; n < 6; ++n) {
      const Matrix3d block = h.block<3, 3>(3 * i, 3 * n);
      if (block.isZero(0.0)) continue;
      for (int j = 0; j < kBeamElementBlocks; ++j) {
        if (m.b(i, j) == 0.0) continue;
        for (int l = 0; l < kBeamElementBlocks; ++l)
          if (m.b(n, l) != 0.0) k.block<3, 3>(3 * j, 3 * l) += (m.b(i, j) * m.b(n, l)) * block;
      }
    }
}

}  // namespace ancfnet
