// Contact couplings that come and go (SystemMatrix::UpdateContactCouplings): a coupling is added
// when a pair needs it, kept while its pair stays near, dropped after it has not been for a
// while; the pattern is rebuilt only when a needed coupling is missing or too many are stale;
// and a matrix whose couplings came and went solves the same system as one built afresh with the
// couplings that remain.

#include <gtest/gtest.h>

#include <random>

#include "ancfnet/assembly/system_matrix.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/solvers/linear_solver.hpp"

namespace ancfnet {
namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

// Six one-element threads side by side, the first clamped at its start: owners 0 … 5.
Model MakeThreads() {
  const CableProperties p =
      MakeCableProperties({.youngs_modulus = 1e9, .density = 1000}, MakeCircleSection(0.002));
  ModelBuilder builder;
  for (int k = 0; k < 6; ++k)
    builder.AddCable({.name = "t" + std::to_string(k),
                      .start = Vector3d(0, 0.01 * k, 0),
                      .end = Vector3d(1, 0.01 * k, 0),
                      .num_elements = 1,
                      .properties = p});
  builder.AddClamp({"t0", 0.0});
  return builder.Build();
}

TEST(ContactCouplings, AddedWhenNeededKeptWhileNearDroppedWhenStale) {
  const Model model = MakeThreads();
  const DofMap dofs = DofMap::FreeCoordinates(model);
  SystemMatrix matrix(model, dofs);
  matrix.set_contact_coupling_settings({.keep_updates = 2, .max_stale_fraction = 0.5});
  const Index model_nonzeros = matrix.matrix().nonZeros();
  EXPECT_EQ(matrix.num_pattern_builds(), 1);

  // Update 1: (0, 2) is needed, (1, 3) only near: both coupled by the one rebuild.
  EXPECT_TRUE(matrix.UpdateContactCouplings({{2, 0}}, {{0, 2}, {3, 1}}));
  EXPECT_EQ(matrix.num_contact_couplings(), 2);
  EXPECT_GE(matrix.FindContactCoupling(0, 2), 0);
  EXPECT_GE(matrix.FindContactCoupling(1, 3), 0);
  // Thread 0 has 6 free coordinates, the others 12: the new entries are the blocks between them.
  EXPECT_EQ(matrix.matrix().nonZeros(), model_nonzeros + 2 * 6 * 12 + 2 * 12 * 12);
  // Updates 2 to 4: only (0, 2) near. (1, 3) turns stale at update 4 (last near at 1), one of
  // two couplings: not more than half, so no rebuild; a near pair not yet coupled, (4, 5), does
  // not force one either.
  for (int update = 2; update <= 4; ++update)
    EXPECT_FALSE(matrix.UpdateContactCouplings({{0, 2}}, {{0, 2}, {4, 5}})) << update;
  EXPECT_GE(matrix.FindContactCoupling(1, 3), 0);
  EXPECT_EQ(matrix.FindContactCoupling(4, 5), -1);
  // Update 5: (2, 4) is needed: the rebuild drops (1, 3) and adds (2, 4) and the near (4, 5).
  EXPECT_TRUE(matrix.UpdateContactCouplings({{0, 2}, {2, 4}}, {{0, 2}, {2, 4}, {4, 5}}));
  EXPECT_EQ(matrix.num_contact_couplings(), 3);
  EXPECT_EQ(matrix.FindContactCoupling(1, 3), -1);
  EXPECT_GE(matrix.FindContactCoupling(2, 4), 0);
  EXPECT_GE(matrix.FindContactCoupling(4, 5), 0);
  EXPECT_EQ(matrix.num_pattern_builds(), 3);
  // Nothing near any more: after 2 updates all three are stale at the third, and the pattern
  // falls back to the model's own.
  EXPECT_FALSE(matrix.UpdateContactCouplings({}, {}));
  EXPECT_FALSE(matrix.UpdateContactCouplings({}, {}));
  EXPECT_TRUE(matrix.UpdateContactCouplings({}, {}));
  EXPECT_EQ(matrix.num_contact_couplings(), 0);
  EXPECT_EQ(matrix.matrix().nonZeros(), model_nonzeros);
}

TEST(ContactCouplings, KeptForGoodWhenAskedTo) {
  const Model model = MakeThreads();
  const DofMap dofs = DofMap::FreeCoordinates(model);
  SystemMatrix matrix(model, dofs);
  matrix.set_contact_coupling_settings({.keep_updates = -1});
  EXPECT_TRUE(matrix.AddContactCouplings({{1, 2}}));
  for (int update = 0; update < 10; ++update) EXPECT_FALSE(matrix.UpdateContactCouplings({}, {}));
  EXPECT_TRUE(matrix.AddContactCouplings({{3, 4}}));
  EXPECT_EQ(matrix.num_contact_couplings(), 2);
}

// Fills the matrix with a diagonally dominant system: each element's block, and a coupling block
// between the owners of every pair of `couplings`.
void Fill(const Model& model, const Pairs& couplings, SystemMatrix* matrix) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  matrix->SetZero();
  for (Index e = 0; e < static_cast<Index>(model.elements().size()); ++e) {
    Matrix12d block = Matrix12d::NullaryExpr([&] { return uniform(random); });
    block += 40.0 * Matrix12d::Identity();
    matrix->AddElementBlock(e, block);
  }
  for (const auto& [a, b] : couplings) {
    const int c = matrix->FindContactCoupling(a, b);
    ASSERT_GE(c, 0);
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        if ((i < 4) != (j < 4))
          matrix->AddContactBlock(c, i, j, Matrix3d::NullaryExpr([&] { return uniform(random); }));
  }
}

TEST(ContactCouplings, MatrixAfterAddsAndDropsSolvesTheSystemOfAFreshOne) {
  const Model model = MakeThreads();
  const DofMap dofs = DofMap::FreeCoordinates(model);
  SystemMatrix pruned(model, dofs);
  pruned.set_contact_coupling_settings({.keep_updates = 1, .max_stale_fraction = 0.0});
  pruned.UpdateContactCouplings({{0, 1}, {1, 2}}, {{0, 1}, {1, 2}, {3, 5}});
  pruned.UpdateContactCouplings({{1, 2}}, {{1, 2}});
  pruned.UpdateContactCouplings({{1, 2}, {2, 5}}, {{1, 2}, {2, 5}});  // drops (0, 1), (3, 5)
  ASSERT_EQ(pruned.num_contact_couplings(), 2);
  const Pairs remaining = {{1, 2}, {2, 5}};
  SystemMatrix fresh(model, dofs);
  fresh.AddContactCouplings(remaining);

  Fill(model, remaining, &pruned);
  Fill(model, remaining, &fresh);
  EXPECT_EQ(pruned.matrix().nonZeros(), fresh.matrix().nonZeros());
  EXPECT_EQ((pruned.matrix() - fresh.matrix()).norm(), 0.0);
  const VectorXd b = VectorXd::LinSpaced(dofs.num_unknowns(), -1.0, 2.0);
  VectorXd x_pruned, x_fresh;
  SparseLinearSolver pruned_solver, fresh_solver;
  ASSERT_TRUE(pruned_solver.Factorize(pruned.matrix()));
  ASSERT_TRUE(fresh_solver.Factorize(fresh.matrix()));
  pruned_solver.Solve(b, &x_pruned);
  fresh_solver.Solve(b, &x_fresh);
  EXPECT_LT((x_pruned - x_fresh).norm(), 1e-12 * x_fresh.norm());
  EXPECT_LT((pruned.matrix() * x_pruned - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace ancfnet
