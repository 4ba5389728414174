#pragma once
/// @file Second-order jets of the ANCF beam's strains: a scalar with its exact gradient and Hessian
/// with respect to the 18 local kinematic quantities at one point of the beam axis,
///   u = [r', r'', d₂, d₃, d₂', d₃'],
/// and the product rule that combines them. Every strain of elements/ancf_beam.hpp is a sum of
/// products of the primitives below (dot products, triple products and powers of |d₂|, |d₃|), so
/// its derivatives follow by the chain rule written out once here (docs/theory.md, "ANCF beam
/// element").

#include <cmath>

#include "ancfnet/common/skew.hpp"
#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Number of local kinematic quantities at a point of the beam axis (six 3-vectors).
inline constexpr int kBeamLocalSize = 18;
using BeamLocalVector = Eigen::Matrix<double, kBeamLocalSize, 1>;
using BeamLocalMatrix = Eigen::Matrix<double, kBeamLocalSize, kBeamLocalSize>;

/// The 3-vector blocks of u: r' (the axial slope), r'', the directors d₂ = r_y and d₃ = r_z, and
/// their derivatives along the axis.
enum BeamLocalBlock : int {
  kSlope = 0,
  kCurvatureVector = 1,
  kD2 = 2,
  kD3 = 3,
  kD2x = 4,
  kD3x = 5
};

/// A scalar function f(u) with ∇f and, when `has_hessian`, ∇²f (otherwise `hess` is left
/// uninitialised, which saves the force-only path most of its work).
struct StrainJet {
  explicit StrainJet(bool with_hessian = false) : has_hessian(with_hessian) {
    grad.setZero();
    if (has_hessian) hess.setZero();
  }
  double value = 0.0;
  bool has_hessian;
  BeamLocalVector grad;
  BeamLocalMatrix hess;
};

/// The 3-vector block `b` of u.
inline Vector3d LocalBlock(const BeamLocalVector& u, int b) { return u.segment<3>(3 * b); }

/// a·b for blocks a ≠ b: ∇ = [b at a, a at b], ∇² = I at (a, b) and (b, a).
inline StrainJet DotJet(const BeamLocalVector& u, int a, int b, bool with_hessian) {
  StrainJet j(with_hessian);
  const Vector3d ua = LocalBlock(u, a);
  const Vector3d ub = LocalBlock(u, b);
  j.value = ua.dot(ub);
  j.grad.segment<3>(3 * a) += ub;
  j.grad.segment<3>(3 * b) += ua;
  if (with_hessian) {
    j.hess.block<3, 3>(3 * a, 3 * b).diagonal().array() += 1.0;
    j.hess.block<3, 3>(3 * b, 3 * a).diagonal().array() += 1.0;
  }
  return j;
}

/// ½ (|a|² − 1) for block a: ∇ = a, ∇² = I.
inline StrainJet HalfStretchJet(const BeamLocalVector& u, int a, bool with_hessian) {
  StrainJet j(with_hessian);
  const Vector3d ua = LocalBlock(u, a);
  j.value = 0.5 * (ua.squaredNorm() - 1.0);
  j.grad.segment<3>(3 * a) = ua;
  if (with_hessian) j.hess.block<3, 3>(3 * a, 3 * a).diagonal().setOnes();
  return j;
}

/// The triple product a·(b × c) of three distinct blocks: ∇ = [b×c, c×a, a×b],
/// ∇²: (a,b) = −[c]×, (a,c) = [b]×, (b,c) = −[a]× and their transposes.
inline StrainJet TripleJet(const BeamLocalVector& u, int a, int b, int c, bool with_hessian) {
  StrainJet j(with_hessian);
  const Vector3d ua = LocalBlock(u, a);
  const Vector3d ub = LocalBlock(u, b);
  const Vector3d uc = LocalBlock(u, c);
  j.value = ua.dot(ub.cross(uc));
  j.grad.segment<3>(3 * a) = ub.cross(uc);
  j.grad.segment<3>(3 * b) = uc.cross(ua);
  j.grad.segment<3>(3 * c) = ua.cross(ub);
  if (with_hessian) {
    const auto set_pair = [&j](int p, int q, const Matrix3d& m) {
      j.hess.block<3, 3>(3 * p, 3 * q) = m;
      j.hess.block<3, 3>(3 * q, 3 * p) = m.transpose();
    };
    set_pair(a, b, -Skew(uc));
    set_pair(a, c, Skew(ub));
    set_pair(b, c, -Skew(ua));
  }
  return j;
}

/// |a|^(−p) for block a, with g = |a|²: ∇ = −p g^(−p/2−1) a,
/// ∇² = −p g^(−p/2−1) I + p (p + 2) g^(−p/2−2) a aᵀ.
inline StrainJet InverseNormPowerJet(const BeamLocalVector& u, int a, int p, bool with_hessian) {
  StrainJet j(with_hessian);
  const Vector3d ua = LocalBlock(u, a);
  const double g = ua.squaredNorm();
  j.value = std::pow(g, -0.5 * p);
  const double s1 = -p * j.value / g;
  j.grad.segment<3>(3 * a) = s1 * ua;
  if (with_hessian) {
    Matrix3d h = (p * (p + 2.0) * j.value / (g * g)) * ua * ua.transpose();
    h.diagonal().array() += s1;
    j.hess.block<3, 3>(3 * a, 3 * a) = h;
  }
  return j;
}

/// Product rule: (fg)' = f g' + g f', (fg)'' = f g'' + g f'' + f' g'ᵀ + g' f'ᵀ.
/// Both factors must have Hessians, or neither.
inline StrainJet operator*(const StrainJet& f, const StrainJet& g) {
  StrainJet j(f.has_hessian);
  j.value = f.value * g.value;
  j.grad = f.value * g.grad + g.value * f.grad;
  if (j.has_hessian) {
    j.hess = f.value * g.hess + g.value * f.hess;
    j.hess.noalias() += f.grad * g.grad.transpose();
    j.hess.noalias() += g.grad * f.grad.transpose();
  }
  return j;
}

/// Linear combination a f + b g.
inline StrainJet Combine(double a, const StrainJet& f, double b, const StrainJet& g) {
  StrainJet j(f.has_hessian);
  j.value = a * f.value + b * g.value;
  j.grad = a * f.grad + b * g.grad;
  if (j.has_hessian) j.hess = a * f.hess + b * g.hess;
  return j;
}

}  // namespace ancfnet
