#pragma once
/// @file Cubic Hermite shape functions of the ANCF cable element.

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Cubic Hermite shape functions at ξ = x/L ∈ [0, 1] and their derivatives with respect to the
/// reference arc length x, so that r = Σ s_i e_i, r' = Σ ds_i e_i, r'' = Σ dds_i e_i with
/// e = [r_A, r_A', r_B, r_B']. Gerstmayr & Shabana (2006), eq. 3; Berzeri & Shabana (2000), eq. 2.
struct HermiteShape {
  Vector4d s;    ///< S1..S4 (dimensionless, S2 and S4 in m)
  Vector4d ds;   ///< dS/dx (1/m, and 1 for the slope functions)
  Vector4d dds;  ///< d²S/dx² (1/m², 1/m)
};

/// Evaluates the shape functions at ξ ∈ [0, 1] for an element of reference length L > 0 (m).
inline HermiteShape CalcHermiteShape(double xi, double length) {
  const double L = length;
  const double x2 = xi * xi;
  const double x3 = x2 * xi;
  HermiteShape h;
  h.s << 1.0 - 3.0 * x2 + 2.0 * x3, L * (xi - 2.0 * x2 + x3), 3.0 * x2 - 2.0 * x3, L * (x3 - x2);
  h.ds << 6.0 * (x2 - xi) / L, 1.0 - 4.0 * xi + 3.0 * x2, 6.0 * (xi - x2) / L, 3.0 * x2 - 2.0 * xi;
  h.dds << (12.0 * xi - 6.0) / (L * L), (6.0 * xi - 4.0) / L, (6.0 - 12.0 * xi) / (L * L),
      (6.0 * xi - 2.0) / L;
  return h;
}

/// Position r(ξ) = S(ξ) e of an element with nodal coordinates e.
inline Vector3d InterpolatePosition(const Vector12d& e, const Vector4d& s) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 4>>(e.data()) * s;
}

/// Generalised force S(ξ)ᵀ f of a force f applied at the point with shape values s (virtual work,
/// Q = Sᵀ f; Shabana 2005, ch. 6).
inline Vector12d DistributeForce(const Vector4d& s, const Vector3d& f) {
  Vector12d q;
  Eigen::Map<Eigen::Matrix<double, 3, 4>>(q.data()) = f * s.transpose();
  return q;
}

}  // namespace ancfnet
