// The VTK `section_d2` and `section_d3` fields (io/vtk_writer.hpp): the directors of a beam
// cable, interpolated linearly along each element, and zero on a cable. A beam along x with
// d₂ = e_z (orientation [0, 0, 1]) has d₃ = e_x × e_z = −e_y; twisted by hand by 0.4 rad at its end
// node, the middle sample of the last element carries the mean of its nodes' directors.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ancfnet/io/test/output_test_files.hpp"
#include "ancfnet/io/vtk_writer.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

TEST(VtkBeamFrame, SectionDirectorsOfABeamAndZerosOfACable) {
  const CableProperties rod =
      MakeCableProperties({.youngs_modulus = 1.0e9, .density = 1000.0}, MakeCircleSection(0.01));
  ModelBuilder builder;
  builder.AddCable({.name = "beam", .start = Vector3d::Zero(), .end = Vector3d(1.0, 0.0, 0.0),
                    .num_elements = 2, .properties = rod,
                    .beam = BeamCableSpec{
                        .material = {.youngs_modulus = 1.0e9, .poisson_ratio = 0.3,
                                     .density = 1000.0},
                        .section = MakeCircleBeamSection(0.01, 0.3),
                        .orientation = Vector3d::UnitZ()}});
  builder.AddCable({.name = "cable", .start = Vector3d(0.0, 1.0, 0.0),
                    .end = Vector3d(1.0, 1.0, 0.0), .num_elements = 1, .properties = rod});
  const Model model = builder.Build();
  State state = MakeInitialState(model);
  const CableNode& tip = model.nodes()[2];
  const double twist = 0.4;
  state.q.segment<3>(tip.section_dof) = Vector3d(0.0, -std::sin(twist), std::cos(twist));
  state.q.segment<3>(tip.section_dof + 3) = Vector3d(0.0, -std::cos(twist), -std::sin(twist));

  const auto dir = test::MakeTestDirectory();
  VtkSeriesWriter writer(dir, "cables", 2);
  writer.WriteFrame(model, state);
  const std::string xml = test::ReadFile(writer.FramePath(0));
  const std::vector<double> d2 = test::ReadDataArray(xml, "section_d2");
  const std::vector<double> d3 = test::ReadDataArray(xml, "section_d3");
  // Beam: 2 elements × 2 + 1 = 5 samples; cable: 3 samples.
  ASSERT_EQ(d2.size(), 3u * 8u);
  ASSERT_EQ(d3.size(), 3u * 8u);
  const auto sample = [](const std::vector<double>& a, int i) {
    return Vector3d(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
  };
  EXPECT_LT((sample(d2, 0) - Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_LT((sample(d3, 0) + Vector3d::UnitY()).norm(), 1e-15);
  const Vector3d twisted(0.0, -std::sin(twist), std::cos(twist));
  EXPECT_LT((sample(d2, 3) - 0.5 * (Vector3d::UnitZ() + twisted)).norm(), 1e-12);
  EXPECT_LT((sample(d2, 4) - twisted).norm(), 1e-12);
  for (int i = 5; i < 8; ++i) {
    EXPECT_EQ(sample(d2, i), Vector3d::Zero());
    EXPECT_EQ(sample(d3, i), Vector3d::Zero());
  }
}

}  // namespace
}  // namespace ancfnet
