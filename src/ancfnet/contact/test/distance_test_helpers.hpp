#pragma once
// Shared helpers of the distance-function tests: seeded random geometry, central differences,
// their check of a signed distance's gradient and Hessian, and a ternary search that minimises
// convex functions independently of the code under test.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "ancfnet/common/types.hpp"

namespace ancfnet {
namespace test {

inline Vector3d RandomVector(std::mt19937* rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return Vector3d(u(*rng), u(*rng), u(*rng));
}

inline Matrix3d RandomRotation(std::mt19937* rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(*rng), g(*rng), g(*rng), g(*rng));
  return q.normalized().toRotationMatrix();
}

// Central differences of a scalar function of N coordinates, step h.
template <int N>
Eigen::Matrix<double, N, 1> CentralGradient(
    const std::function<double(const Eigen::Matrix<double, N, 1>&)>& f,
    const Eigen::Matrix<double, N, 1>& x, double h) {
  Eigen::Matrix<double, N, 1> g;
  for (int i = 0; i < N; ++i) {
    Eigen::Matrix<double, N, 1> xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    g[i] = (f(xp) - f(xm)) / (2 * h);
  }
  return g;
}

// Central differences of a vector function of a point (columns: ∂f/∂x_i).
inline Matrix3d CentralJacobian(const std::function<Vector3d(const Vector3d&)>& f,
                                const Vector3d& x, double h) {
  Matrix3d J;
  for (int i = 0; i < 3; ++i) {
    Vector3d xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    J.col(i) = (f(xp) - f(xm)) / (2 * h);
  }
  return J;
}

// Minimum of a convex function on [lo, hi] by ternary search (interval below 1e-15 after 100
// iterations on [0, 1]).
inline double TernaryMin(const std::function<double(double)>& f, double lo, double hi) {
  for (int it = 0; it < 100 && hi > lo; ++it) {
    const double m1 = lo + (hi - lo) / 3;
    const double m2 = hi - (hi - lo) / 3;
    if (f(m1) <= f(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return f(0.5 * (lo + hi));
}

// Gradient and Hessian of φ against central differences, skipping configurations whose
// perturbations change the region key.
template <class Eval, class Key>
void CheckGradientAndHessian(const Eval& eval, const Key& key, const Vector3d& p, double* worst_g,
                             double* worst_h, int* checked) {
  const auto d = eval(p);
  bool same = true;
  const double h = 1e-6;
  const Vector3d fd = CentralGradient<3>(
      [&](const Vector3d& x) {
        same = same && key(x) == key(p);
        return eval(x).distance;
      },
      p, h);
  const Matrix3d fdh = CentralJacobian(
      [&](const Vector3d& x) {
        same = same && key(x) == key(p);
        return eval(x).normal;
      },
      p, h);
  if (!same || std::abs(d.distance) < 1e-2) return;
  const double eg = (fd - d.normal).norm();
  const double eh = (fdh - d.hessian).norm() / std::max(1.0, d.hessian.norm());
  EXPECT_LT(eg, 1e-6);
  EXPECT_LT(eh, 1e-6);
  *worst_g = std::max(*worst_g, eg);
  *worst_h = std::max(*worst_h, eh);
  ++*checked;
}

}  // namespace test
}  // namespace ancfnet
