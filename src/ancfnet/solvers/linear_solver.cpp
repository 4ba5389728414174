#include "ancfnet/solvers/linear_solver.hpp"

#include <klu.h>

#include <Eigen/SparseLU>
#include <variant>
#include <vector>

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
      outer_.assign(ap, ap + a.cols() + 1);
      inner_.assign(ai, ai + a.nonZeros());
    }
    values_.assign(ax, ax + a.nonZeros());
    if (numeric_ && klu_refactor(ap, ai, ax, symbolic_, numeric_, &common_) &&
        klu_rcond(symbolic_, numeric_, &common_) && common_.rcond > kMinRcondForRefactor) {
      refactored_ = true;
      return true;
    }
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    numeric_ = klu_factor(ap, ai, ax, symbolic_, &common_);
    pivot_values_ = values_;
    refactored_ = false;
    return numeric_ != nullptr && common_.status == KLU_OK;
  }

  void ForgetPattern() {
    if (numeric_) klu_free_numeric(&numeric_, &common_);
    if (symbolic_) klu_free_symbolic(&symbolic_, &common_);
  }

  // The pattern, the values of the last klu_factor (its pivot order is what klu_refactor
  // reuses) and those of the last factorisation.
  void SaveCheckpoint(ArchiveWriter* out) const {
    out->Write(numeric_ != nullptr);
    if (!numeric_) return;
    out->Write(outer_);
    out->Write(inner_);
    out->Write(pivot_values_);
    out->Write(refactored_);
    if (refactored_) out->Write(values_);
  }

  void LoadCheckpoint(ArchiveReader* in) {
    ForgetPattern();
    if (!in->Read<bool>()) return;
    in->Read(&outer_);
    in->Read(&inner_);
    if (outer_.empty() || outer_.back() != static_cast<int>(inner_.size()))
      in->Fail("a linear solver pattern that is not consistent");
    in->Read(&pivot_values_, static_cast<std::int64_t>(inner_.size()));
    refactored_ = in->Read<bool>();
    if (refactored_)
      in->Read(&values_, static_cast<std::int64_t>(inner_.size()));
    else
      values_ = pivot_values_;
    const int n = static_cast<int>(outer_.size()) - 1;
    symbolic_ = klu_analyze(n, outer_.data(), inner_.data(), &common_);
    if (symbolic_)
      numeric_ =
          klu_factor(outer_.data(), inner_.data(), pivot_values_.data(), symbolic_, &common_);
    if (numeric_ && refactored_ &&
        !klu_refactor(outer_.data(), inner_.data(), values_.data(), symbolic_, numeric_, &common_))
      klu_free_numeric(&numeric_, &common_);
    if (!numeric_) in->Fail("its iteration matrix cannot be factorised again");
  }

  void Solve(const VectorXd& b, VectorXd* x) {
    *x = b;
    klu_solve(symbolic_, numeric_, static_cast<int>(x->size()), 1, x->data(), &common_);
  }

 private:
  klu_common common_;
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  std::vector<int> outer_, inner_;
  std::vector<double> pivot_values_, values_;
  bool refactored_ = false;  // the last factorisation reused the pivot order
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
    last_ = a;
    return solver_.info() == Eigen::Success;
  }
  void ForgetPattern() { analysed_ = false; }
  void Solve(const VectorXd& b, VectorXd* x) { *x = solver_.solve(b); }
  // Its factorisations depend on the matrix alone: the last one is kept.
  void SaveCheckpoint(ArchiveWriter* out) const {
    out->Write(analysed_);
    if (!analysed_) return;
    const SparseMatrixd& a = last_;
    out->Write(static_cast<std::int64_t>(a.rows()));
    out->Write(std::vector<int>(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1));
    out->Write(std::vector<int>(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros()));
    out->Write(std::vector<double>(a.valuePtr(), a.valuePtr() + a.nonZeros()));
  }
  void LoadCheckpoint(ArchiveReader* in) {
    analysed_ = false;
    if (!in->Read<bool>()) return;
    const auto n = in->Read<std::int64_t>();
    std::vector<int> outer, inner;
    std::vector<double> values;
    in->Read(&outer, n + 1);
    in->Read(&inner);
    in->Read(&values, static_cast<std::int64_t>(inner.size()));
    if (outer.back() != static_cast<int>(inner.size()))
      in->Fail("a linear solver pattern that is not consistent");
    if (!Factorize(Eigen::Map<const SparseMatrixd>(n, n, static_cast<Index>(values.size()),
                                                   outer.data(), inner.data(), values.data())))
      in->Fail("its iteration matrix cannot be factorised again");
  }

 private:
  Eigen::SparseLU<SparseMatrixd> solver_;
  SparseMatrixd last_;  // the matrix last factorised
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

void SparseLinearSolver::SaveCheckpoint(ArchiveWriter* out) const {
  std::visit([&](const auto& solver) { solver.SaveCheckpoint(out); }, impl_->solver);
}

void SparseLinearSolver::LoadCheckpoint(ArchiveReader* in) {
  std::visit([&](auto& solver) { solver.LoadCheckpoint(in); }, impl_->solver);
}

}  // namespace ancfnet
