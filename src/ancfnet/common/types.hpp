#pragma once
/// @file Eigen aliases and index types shared by every part of ancfnet.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

namespace ancfnet {

/// Index into coordinate vectors and element lists (signed, as Eigen's).
using Index = Eigen::Index;

using Vector3d = Eigen::Vector3d;
using Vector4d = Eigen::Vector4d;
using Matrix3d = Eigen::Matrix3d;
using Matrix4d = Eigen::Matrix4d;
using VectorXd = Eigen::VectorXd;
using MatrixXd = Eigen::MatrixXd;

/// Nodal coordinates of one ANCF cable element: e = [r_A, r_A', r_B, r_B'].
using Vector12d = Eigen::Matrix<double, 12, 1>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;
/// Shape-function matrix S = [S1 I, S2 I, S3 I, S4 I] and its derivatives.
using Matrix3x12d = Eigen::Matrix<double, 3, 12>;

/// Column-major sparse matrix used for the system matrices.
using SparseMatrixd = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Number of coordinates of an ANCF cable node: position r and slope r'.
inline constexpr int kCableNodeDofs = 6;
/// Number of coordinates of an ANCF cable element.
inline constexpr int kCableElementDofs = 12;

}  // namespace ancfnet
