// A linear solver restored from a checkpoint solves bit for bit as the one that wrote it. KLU
// refactorises with the pivot order of its last full factorisation, so after a factorisation of A
// and a refactorisation of B its solutions with B differ in their last bits from those of a fresh
// factorisation of B: the checkpoint must recreate the pivot order, not only the last matrix.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "ancfnet/common/error.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {
namespace {

constexpr int kSize = 12;

// A sparse matrix whose entries follow `value(i, j)` on a band of half-width 3.
template <class Value>
SparseMatrixd MakeMatrix(Value value) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < kSize; ++i)
    for (int j = std::max(0, i - 3); j < std::min(kSize, i + 4); ++j)
      entries.emplace_back(i, j, value(i, j));
  SparseMatrixd a(kSize, kSize);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

// Tiny diagonal: the full factorisation pivots off the diagonal.
SparseMatrixd MakeA() {
  return MakeMatrix([](int i, int j) { return i == j ? 1e-7 : 1.0 + std::sin(1.0 + i + 3.0 * j); });
}
// Diagonally dominant, the same pattern: a fresh factorisation keeps the diagonal.
SparseMatrixd MakeB() {
  return MakeMatrix(
      [](int i, int j) { return i == j ? 10.0 + 0.1 * i : 0.3 * std::cos(2.0 + i - 5.0 * j); });
}

VectorXd Solve(SparseLinearSolver& solver) {
  VectorXd x;
  solver.Solve(VectorXd::LinSpaced(kSize, 0.1, 1.3), &x);
  return x;
}

bool SameBits(const VectorXd& a, const VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

// A solver whose state SaveCheckpoint wrote, recreated by LoadCheckpoint in a new one.
SparseLinearSolver Restored(const SparseLinearSolver& solver) {
  ArchiveWriter out;
  solver.SaveCheckpoint(&out);
  SparseLinearSolver restored;
  ArchiveReader in(out.bytes().data(), out.bytes().size(), "checkpoint");
  restored.LoadCheckpoint(&in);
  in.ExpectEnd();
  return restored;
}

TEST(LinearSolverCheckpoint, ARefactorisationIsRecreatedWithItsPivotOrder) {
  SparseLinearSolver solver;
  ASSERT_TRUE(solver.Factorize(MakeA()));
  ASSERT_TRUE(solver.Factorize(MakeB()));  // refactorised with A's pivot order
  const VectorXd x = Solve(solver);
  SparseLinearSolver restored = Restored(solver);
  EXPECT_TRUE(SameBits(Solve(restored), x));
  // Refactorising the restored solver goes on as the original would.
  const SparseMatrixd c = MakeB() * 1.5;
  ASSERT_TRUE(solver.Factorize(c));
  ASSERT_TRUE(restored.Factorize(c));
  EXPECT_TRUE(SameBits(Solve(restored), Solve(solver)));

  // Why the pivot order is kept: a fresh factorisation of B solves with other last bits.
  SparseLinearSolver fresh;
  ASSERT_TRUE(fresh.Factorize(MakeB()));
  EXPECT_FALSE(SameBits(Solve(fresh), x));
  EXPECT_LT((Solve(fresh) - x).norm(), 1e-12 * x.norm());
}

TEST(LinearSolverCheckpoint, NothingFactorisedRestoresToNothing) {
  SparseLinearSolver solver;
  SparseLinearSolver restored = Restored(solver);
  ASSERT_TRUE(restored.Factorize(MakeB()));
  ASSERT_TRUE(solver.Factorize(MakeB()));
  EXPECT_TRUE(SameBits(Solve(restored), Solve(solver)));
}

TEST(LinearSolverCheckpoint, EveryTruncationIsRefused) {
  SparseLinearSolver solver;
  ASSERT_TRUE(solver.Factorize(MakeA()));
  ASSERT_TRUE(solver.Factorize(MakeB()));
  ArchiveWriter out;
  solver.SaveCheckpoint(&out);
  for (std::size_t size = 0; size < out.bytes().size(); size += 7) {
    SparseLinearSolver restored;
    ArchiveReader in(out.bytes().data(), size, "cut.bin");
    EXPECT_THROW(restored.LoadCheckpoint(&in), InputError) << size;
  }
}

}  // namespace
}  // namespace ancfnet
