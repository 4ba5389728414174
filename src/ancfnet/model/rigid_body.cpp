#include "ancfnet/model/rigid_body.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "ancfnet/common/error.hpp"

namespace ancfnet {

void ValidateInertia(const Matrix3d& j, const std::string& body) {
  if (!j.allFinite())
    throw InputError(fmt::format("body '{}': the inertia tensor must be finite", body));
  if (!j.isApprox(j.transpose(), 1e-9) && (j - j.transpose()).norm() > 1e-12 * j.norm())
    throw InputError(fmt::format("body '{}': the inertia tensor must be symmetric", body));
  const Vector3d moments = Eigen::SelfAdjointEigenSolver<Matrix3d>(j).eigenvalues();
  if (!(moments.minCoeff() > 0.0))
    throw InputError(fmt::format(
        "body '{}': the principal moments of inertia must be > 0 (got {:.6g}, {:.6g}, {:.6g})",
        body, moments[0], moments[1], moments[2]));
  // Sorted ascending: J₁ + J₂ ≥ J₃ is the binding case (relative slack for round-off).
  if (moments[0] + moments[1] < moments[2] * (1.0 - 1e-9))
    throw InputError(fmt::format(
        "body '{}': principal moments {:.6g}, {:.6g}, {:.6g} violate the triangle inequality "
        "J₁ + J₂ ≥ J₃ (no mass distribution has them)",
        body, moments[0], moments[1], moments[2]));
}

void ValidateRotation(const Matrix3d& r, const std::string& what) {
  if (!r.allFinite() || !(r.transpose() * r).isApprox(Matrix3d::Identity(), 1e-6) ||
      !(r.determinant() > 0.0))
    throw InputError(fmt::format("{}: not a rotation matrix (RᵀR = I, det R = 1)", what));
}

}  // namespace ancfnet
