// A net landing on a sphere with regularised friction and no numerical damping (generalised-α
// with ρ∞ = 1): where the middle of the net hits, plain Newton stalls at every step size the time
// loop tries. Tanh friction over 1 cm/s has curvature on the scale of v_r, and a position
// correction δq changes the velocity by γ/(β h) δq: at small steps the full Newton step leaves
// that scale, and the iterates wander instead of converging (the S3 net of 10 × 10 meshes failed
// at t = 0.378 s with h = 2·10⁻⁶ s; docs/theory.md, "Damped Newton"). The default line search
// (`auto`) retries such a step with damped Newton steps, and the run completes.

#include <gtest/gtest.h>

#include <string>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"
#include "net_on_sphere_scene.hpp"

namespace ancfnet {
namespace {

// The S3 scene (examples/net_drop_sphere.yaml) with 4 × 4 meshes and ρ∞ = 1, 0.6 s; `{}` is
// where a line_search key goes.
std::string FrictionLandingScene(const std::string& line_search) {
  return verification::SmallNetOnSphereScene(1.0, 0.35) + R"(analysis:
  type: dynamic
  spectral_radius: 1.0
  time_step: 2.0e-3
  end_time: 0.6
)" + line_search;
}

SolveResult RunFrictionLanding(const std::string& line_search) {
  const Scene scene = ParseScene(FrictionLandingScene(line_search), "friction_landing.yaml");
  State state = MakeInitialState(scene.model);
  return SolveDynamic(
      scene.model, scene.analysis.dynamics, /*output_interval=*/0.01,
      [](const State&, const EnergyAccount&) {}, &state);
}

TEST(FrictionLandingNewton, DampedRetryCarriesTheLandingThatPlainNewtonCannot) {
  const SolveResult plain = RunFrictionLanding("  line_search: never\n");
  EXPECT_FALSE(plain.completed);
  EXPECT_NE(plain.message.find("no convergence"), std::string::npos) << plain.message;
  const SolveResult defaults = RunFrictionLanding("");
  ASSERT_TRUE(defaults.completed) << defaults.message;
  EXPECT_GT(defaults.statistics.steps, 300);
}

}  // namespace
}  // namespace ancfnet
