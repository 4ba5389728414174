// The scale of each kind of coordinate that Newton's convergence norm measures increments against
// (model/coordinate_scales.hpp): the model's length for positions, 1 for gradients and rotations.

#include "ancfnet/model/coordinate_scales.hpp"

#include <gtest/gtest.h>

#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

CableProperties Cord() {
  return MakeCableProperties({.youngs_modulus = 1.0e9, .density = 1000.0},
                             MakeCircleSection(0.002));
}

TEST(CoordinateScales, PositionsAreMeasuredAgainstTheMeanElementLength) {
  ModelBuilder builder;
  // Elements of 0.5 m and 0.25 m: the mean over the 6 elements is (2·0.5 + 4·0.25)/6.
  builder.AddCable({.name = "long",
                    .start = Vector3d(100.0, 0.0, 0.0),
                    .end = Vector3d(101.0, 0.0, 0.0),
                    .num_elements = 2,
                    .properties = Cord()});
  builder.AddCable({.name = "short",
                    .start = Vector3d(0.0, 0.0, 0.0),
                    .end = Vector3d(0.0, 1.0, 0.0),
                    .num_elements = 4,
                    .properties = Cord()});
  builder.AddPointMass("bullet", 0.1, Vector3d(5.0, 5.0, 5.0));
  builder.AddRigidBody({.name = "box", .mass = 1.0, .position = Vector3d(0.0, 0.0, 3.0)});
  const Model model = builder.Build();
  const double length = (2 * 0.5 + 4 * 0.25) / 6.0;
  EXPECT_DOUBLE_EQ(CalcModelLengthScale(model), length);
  const VectorXd scales = CalcCoordinateScales(model);
  ASSERT_EQ(scales.size(), model.num_dofs());
  for (const CableNode& node : model.nodes()) {
    // Wherever the node is (100 m out or at the origin), its position has the same scale.
    EXPECT_TRUE((scales.segment<3>(node.position_dof).array() == length).all());
    EXPECT_TRUE((scales.segment<3>(node.slope_dof).array() == 1.0).all());
  }
  EXPECT_TRUE((scales.segment<3>(model.point_masses()[0].dof).array() == length).all());
  const RigidBody& box = model.rigid_bodies()[0];
  EXPECT_TRUE((scales.segment<3>(box.position_dof()).array() == length).all());
  EXPECT_TRUE((scales.segment<3>(box.rotation_dof()).array() == 1.0).all());
}

TEST(CoordinateScales, WithoutElementsTheBoxRoundMassesAndBodiesGivesTheLength) {
  ModelBuilder builder;
  builder.AddPointMass("a", 0.1, Vector3d(1.0, 2.0, 0.0));
  builder.AddRigidBody({.name = "b", .mass = 1.0, .position = Vector3d(4.0, 6.0, 0.0)});
  EXPECT_DOUBLE_EQ(CalcModelLengthScale(builder.Build()), 5.0);
  ModelBuilder single;
  single.AddRigidBody({.name = "b", .mass = 1.0, .position = Vector3d(4.0, 6.0, 0.0)});
  EXPECT_DOUBLE_EQ(CalcModelLengthScale(single.Build()), 1.0);  // one point: no extent
}

}  // namespace
}  // namespace ancfnet
