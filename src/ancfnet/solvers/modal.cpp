#include "ancfnet/solvers/modal.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ancfnet/common/error.hpp"
#include "ancfnet/forces/forces.hpp"
#include "ancfnet/solvers/damping_model.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {
namespace {

// y = (K − σ M)⁻¹ x with one sparse factorisation per shift (KLU), for Spectra.
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(const SparseMatrixd& k, const SparseMatrixd& m) : k_(k), m_(m) {}
  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }
  void set_shift(double sigma) {
    shifted_ = k_ - sigma * m_;
    if (!solver_.Factorize(shifted_))
      throw SolverError(
          fmt::format("K − σM is singular at σ = {:.6g}: choose another shift", sigma), 0.0);
    x_.resize(k_.rows());
    y_.resize(k_.rows());
  }
  void perform_op(const double* x_in, double* y_out) const {
    x_ = Eigen::Map<const VectorXd>(x_in, k_.rows());
    solver_.Solve(x_, &y_);
    Eigen::Map<VectorXd>(y_out, k_.rows()) = y_;
  }

 private:
  const SparseMatrixd& k_;
  const SparseMatrixd& m_;
  SparseMatrixd shifted_;
  mutable SparseLinearSolver solver_;
  mutable VectorXd x_, y_;
};

struct Eigenpairs {
  bool converged = false;
  VectorXd values;   // ω², ascending
  MatrixXd vectors;  // over the unknowns, M-normalised
};

Eigenpairs SolveShiftInvert(const SparseMatrixd& k, const SparseMatrixd& m, int num_modes,
                            double sigma, double tolerance, int subspace_factor = 1) {
  ShiftInvertOperator op(k, m);
  Spectra::SparseSymMatProd<double> m_op(m);
  const Eigen::Index n = k.rows();
  const Eigen::Index ncv =
      std::min<Eigen::Index>(n, subspace_factor * std::max(2 * num_modes + 1, 20));
  Spectra::SymGEigsShiftSolver<ShiftInvertOperator, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, m_op, num_modes, ncv, sigma);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, tolerance, Spectra::SortRule::SmallestAlge);
  Eigenpairs result;
  result.converged = solver.info() == Spectra::CompInfo::Successful;
  if (!result.converged) return result;
  result.values = solver.eigenvalues();
  result.vectors = solver.eigenvectors();
  return result;
}

// Sparse, symmetrised matrices over the unknowns.
struct LinearSystem {
  SparseMatrixd stiffness, damping, mass;
};

LinearSystem Linearise(const Model& model, const DofMap& dofs, const VectorXd& q,
                       const DampingModel* damping) {
  if (model.num_constraint_equations() > 0)
    throw InputError(
        "modal analysis with ideal joints is not supported yet (the modes would ignore the "
        "joints' constraints); remove the joints or run a static or dynamic analysis");
  if (model.has_free_bodies())
    throw InputError(
        "modal analysis: the model has a free rigid body (its rotation coordinates are not "
        "linearised); make the bodies fixed (motion: fixed)");
  if (!model.contact().targets.empty() || model.contact().self_contact)
    throw InputError(
        "modal analysis: the scene has contact (targets or self_contact), which the linearisation "
        "does not include; remove the contact section to find the free modes");
  Workspace ws(model);
  SystemMatrix matrix(model, dofs);
  const VectorXd rest = VectorXd::Zero(model.num_dofs());
  CalcExternalForces(model, q, 1.0, ws);
  LinearSystem system;
  AssembleIterationMatrix(model, q, rest, {.mass = 0.0, .damping = 0.0, .stiffness = 1.0}, 1.0, ws,
                          &matrix);
  system.stiffness = 0.5 * (matrix.matrix() + SparseMatrixd(matrix.matrix().transpose()));
  AssembleIterationMatrix(model, q, rest, {.mass = 0.0, .damping = 1.0, .stiffness = 0.0}, 1.0, ws,
                          &matrix);
  if (damping) damping->AddRayleighJacobian(1.0, &matrix);
  system.damping = matrix.matrix();
  AssembleMassMatrix(model, ws, &matrix);
  system.mass = matrix.matrix();
  return system;
}

// ζ of each mode from the eigenvalues of the first-order form of ÿ + Φᵀ C Φ ẏ + Λ y = 0.
VectorXd CalcDampingRatios(const MatrixXd& c, const VectorXd& omega,
                           const std::vector<bool>& rigid) {
  const Eigen::Index k = omega.size();
  VectorXd zeta = VectorXd::Zero(k);
  if (c.norm() == 0.0) {
    for (Eigen::Index i = 0; i < k; ++i) zeta[i] = rigid[i] ? std::nan("") : 0.0;
    return zeta;
  }
  MatrixXd a = MatrixXd::Zero(2 * k, 2 * k);
  a.topRightCorner(k, k).setIdentity();
  a.bottomLeftCorner(k, k) = (-omega.array().square()).matrix().asDiagonal();
  a.bottomRightCorner(k, k) = -c;
  const Eigen::VectorXcd s = Eigen::EigenSolver<MatrixXd>(a, false).eigenvalues();
  std::vector<bool> used(s.size(), false);
  for (Eigen::Index i = 0; i < k; ++i) {
    if (rigid[i]) {
      zeta[i] = std::nan("");
      continue;
    }
    // The eigenvalue of positive imaginary part (or real, overdamped) nearest the undamped one.
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < s.size(); ++j) {
      if (used[j] || s[j].imag() < 0.0) continue;
      if (best < 0 || std::abs(std::abs(s[j]) - omega[i]) < std::abs(std::abs(s[best]) - omega[i]))
        best = j;
    }
    if (best < 0) continue;
    used[best] = true;
    zeta[i] = -s[best].real() / std::abs(s[best]);
  }
  return zeta;
}

UndampedModes SolveUndamped(const Model& model, const DofMap& dofs, const LinearSystem& system,
                            const ModalSettings& settings) {
  const Index n = dofs.num_unknowns();
  if (settings.num_modes < 1 || settings.num_modes >= n)
    throw InputError(fmt::format("modes: asked for {} of a model with {} unknowns (1 … {})",
                                 settings.num_modes, n, n - 1));
  const double scale = system.stiffness.diagonal().cwiseAbs().maxCoeff() /
                       system.mass.diagonal().cwiseAbs().maxCoeff();
  double sigma = settings.shift;
  if (sigma == 0.0) {
    // A first pass with a shift far below any elastic eigenvalue of the model finds the lowest
    // one; the real solve then shifts to just below it, where Lanczos converges fast.
    const Eigenpairs probe =
        SolveShiftInvert(system.stiffness, system.mass, 1, -1e-12 * scale, settings.tolerance);
    const double lowest = probe.converged ? std::max(probe.values[0], 0.0) : 0.0;
    sigma = lowest > 1e-10 * scale ? -0.5 * lowest : -1e-6 * scale;
  }
  // Clustered eigenvalues (a slack rope's or net's near-mechanisms, far below |σ|) are poorly
  // separated by the transformation: retry with a larger Krylov subspace, then with the shift
  // moved towards them.
  Eigenpairs pairs;
  for (const auto& [factor, move] : {std::pair{1, 1.0}, {3, 1.0}, {3, 1e-4}, {3, 1e-8}}) {
    if (settings.shift != 0.0 && move != 1.0) break;  // the user's shift stays
    pairs = SolveShiftInvert(system.stiffness, system.mass, settings.num_modes, sigma * move,
                             settings.tolerance, factor);
    if (pairs.converged) break;
  }
  UndampedModes modes;
  if (!pairs.converged) {
    modes.message = fmt::format("the eigensolver did not converge for {} modes at σ = {:.6g}",
                                settings.num_modes, sigma);
    return modes;
  }
  modes.converged = true;
  modes.omega_squared = pairs.values;
  // Rigid modes: ω² at the round-off of K, far below any elastic one.
  modes.rigid.assign(pairs.values.size(), false);
  for (Eigen::Index i = 0; i < pairs.values.size(); ++i)
    modes.rigid[i] = std::abs(pairs.values[i]) <= 1e-9 * scale;
  modes.shapes = MatrixXd::Zero(model.num_dofs(), pairs.values.size());
  for (Index u = 0; u < n; ++u) modes.shapes.row(dofs.coordinates()[u]) = pairs.vectors.row(u);
  return modes;
}

}  // namespace

UndampedModes CalcUndampedModes(const Model& model, const VectorXd& q,
                                const ModalSettings& settings) {
  const DofMap dofs = DofMap::FreeCoordinates(model);
  const LinearSystem system = Linearise(model, dofs, q, nullptr);
  return SolveUndamped(model, dofs, system, settings);
}

ModalResult CalcModes(const Model& model, const VectorXd& q, const ModalSettings& settings) {
  const DofMap dofs = DofMap::FreeCoordinates(model);
  const DampingModel damping(model);
  const LinearSystem system = Linearise(model, dofs, q, &damping);
  const UndampedModes undamped = SolveUndamped(model, dofs, system, settings);
  ModalResult result;
  result.message = undamped.message;
  if (!undamped.converged) return result;
  result.converged = true;
  result.rigid = undamped.rigid;
  result.omega = undamped.omega_squared.cwiseMax(0.0).cwiseSqrt();
  for (Eigen::Index i = 0; i < result.omega.size(); ++i)
    if (result.rigid[i]) result.omega[i] = 0.0;
  result.frequency_hz = result.omega / (2.0 * std::numbers::pi);
  result.shapes = undamped.shapes;
  // Φᵀ C Φ over the unknowns, plus the dense modal damping matrix.
  MatrixXd free_shapes(dofs.num_unknowns(), result.shapes.cols());
  for (Index u = 0; u < dofs.num_unknowns(); ++u)
    free_shapes.row(u) = result.shapes.row(dofs.coordinates()[u]);
  const MatrixXd projected = free_shapes.transpose() * (system.damping * free_shapes) +
                             damping.ProjectModal(result.shapes);
  result.damping_ratio = CalcDampingRatios(projected, result.omega, result.rigid);
  return result;
}

}  // namespace ancfnet
