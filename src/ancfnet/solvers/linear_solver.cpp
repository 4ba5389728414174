#include "ancfnet/solvers/linear_solver.hpp"

#include <klu.h>

#include <Eigen/SparseLU>
#include <variant>

namespace ancfnet {
namespace {

// Reciprocal condition estimate below which refactorisation with the old pivot order is not
// trusted and a factorisation with a fresh pivot search is done instead.
constexpr double kMinRcondForRefactor = 1e-12;

// SuiteSparse KLU called directly (Davis & Palamadai Natarajan 2010): the symbolic analysis
// (BTF + AMD ordering) is done once, and later factorisations reuse the pivot sequence with
// klu_refactor, which neither searches pivots nor allocates. Eigen's KLUSupport redoes klu_factor
// every time, so it is not used here.
class KluFactorization {
 public:
  KluFactorization() { klu_defaults(&common_); }
  ~KluFactorization() { ForgetPattern(); }
  KluFactorization(const KluFactorization&) = delete;
  KluFactorization& operator=(const KluFactorization&) = delete;

  bool Factorize(const SparseMatrixd& a) {
    // KLU reads the compressed columns in place; the matrix outlives the factorisation call.
    auto* ap = const_cast<int*>(a.outerIndexPtr());
    auto* ai = const_cast<int*>(a.innerIndexPtr());
    auto* ax = const_cast<double*>(a.valuePtr());
    if (!symbolic_) {
      symbolic_ = klu_analyze(static_cast<int>(a.rows()), ap, ai, &common_);
      if (!symbolic_) return false;
    }
    if (numeric_ && klu_refactor(ap, ai, ax, symbolic_, numeric_, &common_) &&
        klu_rcond(symbolic_, numeric_, &common_) && common_.rcond > kMinRcondForRefactor)
      return true;
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    numeric_ = klu_factor(ap, ai, ax, symbolic_, &common_);
    return numeric_ != nullptr && common_.status == KLU_OK;
  }

  void ForgetPattern() {
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
  }

  void Solve(const VectorXd& b, VectorXd* x) {
    *x = b;
    klu_solve(symbolic_, numeric_, static_cast<int>(x->size()), 1, x->data(), &common_);
  }

 private:
  klu_common common_;
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
};

// Eigen's supernodal SparseLU: pattern analysed once, numeric factorisation each time.
class EigenSparseLu {
 public:
  bool Factorize(const SparseMatrixd& a) {
    if (!analysed_) {
      solver_.analyzePattern(a);
      analysed_ = true;
    }
    solver_.factorize(a);
    return solver_.info() == Eigen::Success;
  }
  void ForgetPattern() { analysed_ = false; }
  void Solve(const VectorXd& b, VectorXd* x) { *x = solver_.solve(b); }

 private:
  Eigen::SparseLU<SparseMatrixd> solver_;
  bool analysed_ = false;
};

}  // namespace

struct SparseLinearSolver::Impl {
  std::variant<KluFactorization, EigenSparseLu> solver;
};

SparseLinearSolver::SparseLinearSolver(LinearSolverType type) : impl_(std::make_unique<Impl>()) {
  if (type == LinearSolverType::kSparseLu) impl_->solver.emplace<EigenSparseLu>();
}

SparseLinearSolver::~SparseLinearSolver() = default;
SparseLinearSolver::SparseLinearSolver(SparseLinearSolver&&) noexcept = default;
SparseLinearSolver& SparseLinearSolver::operator=(SparseLinearSolver&&) noexcept = default;

bool SparseLinearSolver::Factorize(const SparseMatrixd& a) {
  return std::visit([&](auto& solver) { return solver.Factorize(a); }, impl_->solver);
}

void SparseLinearSolver::ForgetPattern() {
  std::visit([](auto& solver) { solver.ForgetPattern(); }, impl_->solver);
}

void SparseLinearSolver::Solve(const VectorXd& b, VectorXd* x) {
  std::visit([&](auto& solver) { solver.Solve(b, x); }, impl_->solver);
}

}  // namespace ancfnet
