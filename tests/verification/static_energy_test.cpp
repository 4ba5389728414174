// Energy account along a static load path: with the load factor λ raised in steps, the strain
// energy stored must equal the work of the loads (point force and the growing gravity load),
// U + V − W = 0 up to the trapezoidal rule's error over the increments.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/solvers/static_solver.hpp"
#include "verification_scenes.hpp"

namespace ancfnet {
namespace {

TEST(StaticEnergy, BalanceHoldsAlongTheLoadPathWithGravity) {
  ModelBuilder builder = verification::MakeCantilever(8);
  builder.SetGravity(Vector3d(0.0, 0.0, -9.81));
  builder.AddPointForce({"beam", 1.0}, Vector3d(0.0, 0.0, -100.0));
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  StaticSettings settings;
  settings.load_steps = 8;
  double worst = 0.0;
  double work = 0.0;
  double first_gravity = 1.0;
  bool first = true;
  const SolveResult result = SolveStatic(
      model, settings,
      [&](const State&, const EnergyAccount& e) {
        if (first) first_gravity = e.gravity;
        first = false;
        worst = std::max(worst, std::abs(e.kinetic + e.strain + e.gravity + e.dissipated - e.work));
        work = e.work;
      },
      &state);
  ASSERT_TRUE(result.completed) << result.message;
  EXPECT_EQ(first_gravity, 0.0);  // λ = 0: no gravity load yet
  EXPECT_GT(work, 5.0);           // measured 9.39 J in all
  EXPECT_LT(worst, 5e-4 * work);  // measured 3.4e-4 of the work (trapezoidal rule), at λ = 1
}

}  // namespace
}  // namespace ancfnet
