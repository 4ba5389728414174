#include "ancfnet/solvers/linear_solver.hpp"

#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <variant>

namespace ancfnet {

struct SparseLinearSolver::Impl {
  std::variant<Eigen::KLU<SparseMatrixd>, Eigen::SparseLU<SparseMatrixd>> solver;
  bool analysed = false;
};

SparseLinearSolver::SparseLinearSolver(LinearSolverType type) : impl_(std::make_unique<Impl>()) {
  if (type == LinearSolverType::kSparseLu) impl_->solver.emplace<Eigen::SparseLU<SparseMatrixd>>();
}

SparseLinearSolver::~SparseLinearSolver() = default;
SparseLinearSolver::SparseLinearSolver(SparseLinearSolver&&) noexcept = default;
SparseLinearSolver& SparseLinearSolver::operator=(SparseLinearSolver&&) noexcept = default;

bool SparseLinearSolver::Factorize(const SparseMatrixd& a) {
  return std::visit(
      [&](auto& solver) {
        if (!impl_->analysed) {
          solver.analyzePattern(a);
          impl_->analysed = true;
        }
        solver.factorize(a);
        return solver.info() == Eigen::Success;
      },
      impl_->solver);
}

void SparseLinearSolver::Solve(const VectorXd& b, VectorXd* x) {
  std::visit([&](auto& solver) { *x = solver.solve(b); }, impl_->solver);
}

}  // namespace ancfnet
