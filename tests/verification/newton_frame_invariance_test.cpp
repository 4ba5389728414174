// Newton's convergence test does not depend on where a model sits or how it is turned (issue 17):
// a pendulum cable far from the origin and turned about an oblique axis, with gravity turned
// with it, takes the same Newton iterations and follows the same motion as the same pendulum at
// the origin. With weights atol + rtol |qᵢ| the far pendulum was held to a tolerance a thousand
// times looser in its positions, and the near one to atol alone in the slope components that
// happen to be 0.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

struct PendulumRun {
  std::vector<Vector3d> tip;  // at every output, in the pendulum's own frame
  long iterations = 0;
};

PendulumRun RunPendulum(const Vector3d& offset, const Matrix3d& rotation) {
  const Material material{.youngs_modulus = 2.0e9, .density = 1200.0};
  ModelBuilder builder;
  builder.SetGravity(rotation * Vector3d(0.0, 0.0, -9.81));
  builder.AddCable({.name = "rope",
                    .start = offset,
                    .end = offset + rotation * Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 8,
                    .properties = MakeCableProperties(material, MakeCircleSection(0.004))});
  builder.AddPin({"rope", 0.0});
  const Model model = builder.Build();
  DynamicSettings settings;  // default tolerances: the point of the test
  settings.time_step = 1e-3;
  settings.end_time = 0.3;
  State state = MakeInitialState(model);
  const MaterialPoint tip = model.LocateCablePoint(0, 1.0);
  PendulumRun run;
  const SolveResult result = SolveDynamic(
      model, settings, 0.0,
      [&](const State& s, const EnergyAccount&) {
        run.tip.push_back(rotation.transpose() * (model.Interpolate(tip, s.q) - offset));
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  run.iterations = result.statistics.newton_iterations;
  return run;
}

TEST(NewtonFrameInvariance, AFarTurnedPendulumConvergesLikeOneAtTheOrigin) {
  const PendulumRun home = RunPendulum(Vector3d::Zero(), Matrix3d::Identity());
  const Matrix3d turned = Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, 3.0).normalized()).matrix();
  const PendulumRun away = RunPendulum(Vector3d(800.0, -600.0, 300.0), turned);
  ASSERT_EQ(home.tip.size(), away.tip.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < home.tip.size(); ++i)
    largest = std::max(largest, (home.tip[i] - away.tip[i]).norm());
  // The tip swings through about 1 m; the runs agree to the convergence tolerance, rtol L with
  // L = 0.125 m, and not to the 10⁻³ m that rtol |q| allows 1000 m out.
  EXPECT_LT(largest, 1e-6);
  EXPECT_NEAR(static_cast<double>(away.iterations), static_cast<double>(home.iterations),
              0.02 * static_cast<double>(home.iterations));
}

}  // namespace
}  // namespace ancfnet
