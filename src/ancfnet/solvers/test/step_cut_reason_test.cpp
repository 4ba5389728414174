#include <gtest/gtest.h>

#include "ancfnet/solvers/solve_result.hpp"

namespace ancfnet {
namespace {

// Failures that differ only in numbers count as one reason; words with hyphens stay.
TEST(StepCutReason, ReplacesEveryNumberAndKeepsTheWords) {
  EXPECT_EQ(StepCutReason("no convergence in 12 iterations"), "no convergence in # iterations");
  EXPECT_EQ(StepCutReason("self-contact: element 17 and point mass 3 passed through each other"),
            "self-contact: element # and point mass # passed through each other");
  EXPECT_EQ(StepCutReason("the contact probe of element 4 at ξ = 0.125 sank 1.5e-05 m into "
                          "target 'hull' in one step (more than 0.05 of its radius)"),
            "the contact probe of element # at ξ = # sank # m into target 'hull' in one step "
            "(more than # of its radius)");
  EXPECT_EQ(StepCutReason("a primitive moved -3.2E+2 m"), "a primitive moved # m");
}

}  // namespace
}  // namespace ancfnet
