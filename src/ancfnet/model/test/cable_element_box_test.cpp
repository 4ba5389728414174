// The box of a cable element's centre line (model/cable_element_box.hpp): for random nodal
// positions and slopes, every point of the cubic Hermite curve lies in it, and it is tight where
// the curve reaches its control points (the ends).

#include "ancfnet/model/cable_element_box.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {
namespace {

TEST(CableElementBox, HoldsTheWholeCentreLine) {
  ModelBuilder builder;
  builder.AddCable({.name = "a",
                    .start = Vector3d::Zero(),
                    .end = Vector3d(1.2, 0.0, 0.0),
                    .num_elements = 2,
                    .properties = MakeCableProperties({.youngs_modulus = 1e9, .density = 1000},
                                                      MakeCircleSection(0.002))});
  const Model model = builder.Build();
  const CableElement& element = model.elements()[1];
  const double length = element.parameters.length;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorXd q(model.num_dofs());
  double largest_excess = -1.0;
  for (int trial = 0; trial < 200; ++trial) {
    // Slopes up to 3 times the chord's scale: loops and kinks the box must still hold.
    for (Index i = 0; i < q.size(); ++i) q[i] = 3.0 * uniform(random);
    const Aabb box = CalcCableElementBox(model, 1, q);
    for (int j = 0; j <= 200; ++j) {
      const HermiteShape shape = CalcHermiteShape(j / 200.0, length);
      Vector3d r = Vector3d::Zero();
      for (int k = 0; k < 4; ++k) r += shape.s[k] * q.segment<3>(element.dofs[3 * k]);
      largest_excess = std::max(largest_excess, (r - box.max).maxCoeff());
      largest_excess = std::max(largest_excess, (box.min - r).maxCoeff());
    }
    // The ends are control points: on the box.
    EXPECT_EQ(box.SquaredDistanceTo(q.segment<3>(element.dofs[0])), 0.0);
  }
  EXPECT_LE(largest_excess, 1e-12);
  // Some curve point touches the box's face (the box is the control points' and not larger).
  EXPECT_GT(largest_excess, -1e-3);
}

TEST(Aabb, SquaredDistanceIsZeroInsideAndPythagoreanOutside) {
  const Aabb box{Vector3d(-1, -2, -3), Vector3d(1, 2, 3)};
  EXPECT_EQ(box.SquaredDistanceTo(Vector3d(0.5, -1.0, 2.0)), 0.0);
  EXPECT_DOUBLE_EQ(box.SquaredDistanceTo(Vector3d(4.0, 0.0, 0.0)), 9.0);
  EXPECT_DOUBLE_EQ(box.SquaredDistanceTo(Vector3d(2.0, -4.0, 5.0)), 1.0 + 4.0 + 4.0);
}

}  // namespace
}  // namespace ancfnet
