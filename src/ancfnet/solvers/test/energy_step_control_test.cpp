// The energy step control (solvers/energy_step_control.hpp) on hand-made energy accounts: a
// step within its budget is not cut, one that changes the balance by more is cut by 0.9 e*/e (at
// most to a quarter), whichever the sign, the scale grows with the energy met, and η = 0 turns
// the control off.

#include "ancfnet/solvers/energy_step_control.hpp"

#include <gtest/gtest.h>

namespace ancfnet {
namespace {

// A run of 1 s whose energy scale is 100 J: with η = 0.01 a step of 1 ms may spend 1e-3 J.
EnergyAccount Initial() { return {.kinetic = 60.0, .strain = 40.0}; }

TEST(EnergyStepControl, AStepWithinItsBudgetIsNotCut) {
  EnergyStepControl control(0.01, 0.0, 1.0, Initial());
  EnergyAccount next = Initial();
  next.kinetic += 0.9e-3;  // the balance changed by 0.9 e*
  EXPECT_EQ(control.Cut(1e-3, next), 1.0);
  EXPECT_FALSE(control.may_grow());  // more than half the budget spent
  next.kinetic += 0.4e-3;            // 0.4 e*
  EXPECT_EQ(control.Cut(1e-3, next), 1.0);
  EXPECT_TRUE(control.may_grow());
}

TEST(EnergyStepControl, AStepOverItsBudgetCutsTheNextInProportion) {
  EnergyStepControl control(0.01, 0.0, 1.0, Initial());
  EnergyAccount next = Initial();
  next.dissipated = -3e-3;  // the balance rises by 3 e*
  next.kinetic += 6e-3;
  EXPECT_NEAR(control.Cut(1e-3, next), 0.9 / 3.0, 1e-4);
  next.kinetic += 1.0;  // far over: cut to a quarter, no less
  EXPECT_EQ(control.Cut(1e-3, next), 0.25);
}

TEST(EnergyStepControl, EnergyLostCountsAsEnergyCreated) {
  EnergyStepControl control(0.01, 0.0, 1.0, Initial());
  EnergyAccount next = Initial();
  next.kinetic -= 2e-3;  // the balance fell by 2 e*
  EXPECT_NEAR(control.Cut(1e-3, next), 0.45, 1e-4);
  EXPECT_FALSE(control.may_grow());
}

TEST(EnergyStepControl, TheScaleGrowsWithTheEnergyMet) {
  EnergyStepControl control(0.01, 0.0, 1.0, Initial());
  EnergyAccount next = Initial();
  next.work = 100.0;  // work done: the scale is now 300 J (e* = 3e-3 J), the balance unchanged
  next.kinetic += 100.0;
  EXPECT_EQ(control.Cut(1e-3, next), 1.0);
  next.kinetic += 2.5e-3;  // within the tripled budget
  EXPECT_EQ(control.Cut(1e-3, next), 1.0);
  next.kinetic += 6e-3;  // 2 e*
  EXPECT_NEAR(control.Cut(1e-3, next), 0.45, 1e-4);
}

TEST(EnergyStepControl, ZeroDriftTurnsItOff) {
  EnergyStepControl control(0.0, 0.0, 1.0, Initial());
  EnergyAccount next = Initial();
  next.kinetic += 50.0;
  EXPECT_FALSE(control.enabled());
  EXPECT_EQ(control.Cut(1e-3, next), 1.0);
  EXPECT_TRUE(control.may_grow());
}

}  // namespace
}  // namespace ancfnet
