// Net probes on thread tensions: the largest tension of a net and which thread carries it, for a
// configuration whose strains are known exactly.

#include "ancfnet/analysis/probe.hpp"

#include <gtest/gtest.h>

#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

// Three knots on the x-axis at 0, 1, 2 m joined by two 1 m threads (ideal knots). The second
// thread is stretched uniformly by λ = 1.02 (its far knot moved to 2.02 m, its slopes λ e_x):
// ε = (λ² − 1)/2 there, none in the first. Its tension is the section force EA ε λ.
TEST(NetProbe, MaxTensionFindsTheStretchedThread) {
  NetSpec spec;
  spec.name = "line";
  spec.topology =
      MakeGraphNet({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(2, 0, 0)}, {{0, 1}, {1, 2}});
  spec.thread =
      MakeCableProperties({.youngs_modulus = 1e9, .density = 1000}, MakeCircleSection(0.002));
  spec.thread.tension_only = true;
  ModelBuilder builder;
  AddNet(builder, spec);
  const Model model = builder.Build();
  const Net& net = model.nets()[0];
  State state = MakeInitialState(model);
  const double stretch = 1.02;
  state.q[model.point_masses()[net.knots[2]].dof] = 2.0 + stretch - 1.0;
  const Cable& second = model.cables()[net.threads[1]];
  for (Index node = second.first_node; node <= second.first_node + second.num_elements; ++node)
    state.q.segment<3>(model.NodeSlopeDof(node)) = Vector3d(stretch, 0, 0);

  const ThreadTension t = CalcMaxThreadTension(model, net, state.q);
  const double expected = spec.thread.axial_stiffness * 0.5 * (stretch * stretch - 1.0) * stretch;
  EXPECT_NEAR(t.tension, expected, 1e-9 * expected);
  EXPECT_EQ(t.thread, 1);

  Probe probe;
  probe.name = "pull";
  probe.quantity = ProbeQuantity::kMaxTension;
  probe.net = 0;
  EXPECT_EQ(ProbeColumns(probe), (std::vector<std::string>{"pull.tension", "pull.thread"}));
  std::vector<double> values;
  EvaluateProbe(probe, model, state, {}, {}, &values);
  EXPECT_EQ(values, (std::vector<double>{t.tension, 1.0}));
}

TEST(NetProbe, CentroidVelocityIsTheMeanKnotVelocity) {
  NetSpec spec;
  spec.name = "line";
  spec.topology = MakeGraphNet({Vector3d(0, 0, 0), Vector3d(1, 0, 0)}, {{0, 1}});
  spec.thread =
      MakeRopeProperties({.youngs_modulus = 1e9, .density = 1000}, MakeCircleSection(0.002));
  spec.knot_masses = {{0, 0.1, Vector3d(1, 2, 3)}, {1, 0.1, Vector3d(3, 0, -1)}};
  ModelBuilder builder;
  AddNet(builder, spec);
  const Model model = builder.Build();
  Probe probe;
  probe.name = "c";
  probe.quantity = ProbeQuantity::kCentroidVelocity;
  probe.net = 0;
  EXPECT_EQ(ProbeColumns(probe), (std::vector<std::string>{"c.vx", "c.vy", "c.vz"}));
  std::vector<double> values;
  EvaluateProbe(probe, model, MakeInitialState(model), {}, {}, &values);
  EXPECT_EQ(values, (std::vector<double>{2.0, 1.0, 1.0}));
}

}  // namespace
}  // namespace ancfnet
