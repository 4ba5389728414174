// Deployment of a packed net by four corner bullets (examples/net_deploy.yaml): the mouth area
// first grows, reaches a maximum as the threads come taut, then shrinks as the bullets are
// pulled back; the maximum and its time converge as the threads get more elements.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/integrators/dynamic_solver.hpp"
#include "ancfnet/io/scene_loader.hpp"

namespace ancfnet {
namespace {

struct Peak {
  double area = 0.0;
  double time = 0.0;
  double final_area = 0.0;
  double first_area = 0.0;
};

Peak Deploy(int elements_per_thread) {
  // CTest sets ANCFNET_SOURCE_DIR; by hand, run from the repository's root.
  const char* dir = std::getenv("ANCFNET_SOURCE_DIR");
  const std::filesystem::path root = dir ? dir : ".";
  std::ifstream file(root / "examples/net_deploy.yaml");
  EXPECT_TRUE(file) << "cannot open " << (root / "examples/net_deploy.yaml");
  std::stringstream text;
  text << file.rdbuf();
  std::string yaml = text.str();
  yaml.replace(yaml.find("    material: dyneema"), 0,
               "    elements_per_thread: " + std::to_string(elements_per_thread) + "\n");
  const Scene scene = ParseScene(yaml, "net_deploy.yaml");
  const Probe& mouth = scene.probes[0];
  EXPECT_EQ(mouth.quantity, ProbeQuantity::kMouthArea);
  Peak peak;
  State state = MakeInitialState(scene.model);
  bool first = true;
  const SolveResult result = SolveDynamic(
      scene.model, scene.analysis.dynamics, 0.01,
      [&](const State& s, const EnergyAccount& e) {
        std::vector<double> area;
        EvaluateProbe(mouth, scene.model, s, e, {}, &area);
        if (first) peak.first_area = area[0];
        first = false;
        if (area[0] > peak.area) peak = {area[0], s.t, area[0], peak.first_area};
        peak.final_area = area[0];
      },
      &state);
  EXPECT_TRUE(result.completed) << result.message;
  return peak;
}

TEST(NetDeployment, MouthAreaGrowsPeaksAndShrinksAndConverges) {
  const Peak coarse = Deploy(1);
  const Peak fine = Deploy(2);
  std::printf("max mouth area %.3f m² at %.2f s (1 element/thread), %.3f m² at %.2f s (2)\n",
              coarse.area, coarse.time, fine.area, fine.time);
  for (const Peak& p : {coarse, fine}) {
    EXPECT_GT(p.area, 10.0 * p.first_area);  // opens from the packed 1 m² to most of 25 m²
    EXPECT_LT(p.area, 25.0);                 // never beyond the design area
    EXPECT_GT(p.time, 0.3);
    EXPECT_LT(p.time, 1.1);                 // the peak is inside the run ...
    EXPECT_LT(p.final_area, 0.7 * p.area);  // ... and the mouth closes again after it
  }
  EXPECT_NEAR(fine.area, coarse.area, 0.05 * coarse.area);
  EXPECT_NEAR(fine.time, coarse.time, 0.05);
}

}  // namespace
}  // namespace ancfnet
