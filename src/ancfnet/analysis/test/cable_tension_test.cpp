// The stations of the tension recovery along a cable: midpoint forces of the elements, nodes
// between them interpolated, the cable's ends extrapolated, a lone element's ends from its Gauss
// points; and the largest tension over the stations.

#include "ancfnet/analysis/cable_tension.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ancfnet/elements/hermite_shape.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {
namespace {

// Cable "a" of 3 elements (1.5 m along x) and cable "b" of one (1 m along y), steel of 4 mm,
// deformed and stretched without symmetry.
struct Deformed {
  Model model;
  VectorXd q;
};

Deformed MakeDeformed() {
  const CableProperties properties =
      MakeCableProperties({.youngs_modulus = 2.0e11, .density = 7850.0}, MakeCircleSection(4e-3));
  ModelBuilder builder;
  builder.AddCable({"a", Vector3d::Zero(), Vector3d(1.5, 0, 0), 3, properties});
  builder.AddCable({"b", Vector3d::Zero(), Vector3d(0, 1.0, 0), 1, properties});
  Deformed d;
  d.model = builder.Build();
  d.q = MakeInitialState(d.model).q;
  for (Index i = 0; i < d.model.num_dofs(); ++i)
    d.q[i] = 1.001 * d.q[i] + 1e-3 * std::sin(1.3 * static_cast<double>(i) + 0.2);
  return d;
}

Vector3d Midpoint(const Deformed& d, Index element) {
  const CableElement& el = d.model.elements()[element];
  return CalcCableMidpointForce(el.parameters, d.model.Gather(el, d.q));
}

void ExpectNear(const Vector3d& actual, const Vector3d& expected) {
  EXPECT_LT((actual - expected).norm(), 1e-12 * expected.norm())
      << actual.transpose() << " vs " << expected.transpose();
}

TEST(CableTension, StationsInterpolateAndExtrapolateTheMidpointForces) {
  const Deformed d = MakeDeformed();
  const Cable& a = d.model.cables()[0];
  const Vector3d f0 = Midpoint(d, 0), f1 = Midpoint(d, 1), f2 = Midpoint(d, 2);
  const CableStationForces s0 = CalcCableStationForces(d.model, a, 0, d.q);
  const CableStationForces s1 = CalcCableStationForces(d.model, a, 1, d.q);
  const CableStationForces s2 = CalcCableStationForces(d.model, a, 2, d.q);
  ExpectNear(s0.start, 1.5 * f0 - 0.5 * f1);  // the line through the first two midpoints
  ExpectNear(s0.middle, f0);
  ExpectNear(s0.end, 0.5 * (f0 + f1));
  ExpectNear(s1.start, 0.5 * (f0 + f1));  // both elements agree at a shared node
  ExpectNear(s1.middle, f1);
  ExpectNear(s1.end, 0.5 * (f1 + f2));
  ExpectNear(s2.start, 0.5 * (f1 + f2));
  ExpectNear(s2.end, 1.5 * f2 - 0.5 * f1);
}

TEST(CableTension, LoneElementEndsComeFromItsGaussPoints) {
  const Deformed d = MakeDeformed();
  const Cable& b = d.model.cables()[1];
  const CableElement& el = d.model.elements()[b.first_element];
  const Vector12d e = d.model.Gather(el, d.q);
  const CableStationForces s = CalcCableStationForces(d.model, b, 0, d.q);
  ExpectNear(s.middle, CalcCableMidpointForce(el.parameters, e));
  for (double xi : {0.0, 1.0}) {
    const Vector3d tangent = (Eigen::Map<const Eigen::Matrix<double, 3, 4>>(e.data()) *
                              CalcHermiteShape(xi, el.parameters.length).ds)
                                 .normalized();
    ExpectNear(xi == 0.0 ? s.start : s.end,
               CalcCableGaussPointTension(el.parameters, e, xi) * tangent);
  }
}

TEST(CableTension, MaxTensionIsTheLargestStationTension) {
  const Deformed d = MakeDeformed();
  for (const Cable& cable : d.model.cables()) {
    double expected = -1e300;
    for (Index k = 0; k < cable.num_elements; ++k) {
      const CableElement& el = d.model.elements()[cable.first_element + k];
      const CableStationForces s = CalcCableStationForces(d.model, cable, k, d.q);
      for (double xi : {0.0, 0.5, 1.0})
        expected = std::max(expected,
                            CalcCableStationTension(el.parameters, d.model.Gather(el, d.q), s, xi));
    }
    EXPECT_GT(expected, 0.0);  // stretched by 0.1 %
    EXPECT_EQ(CalcCableMaxTension(d.model, cable, d.q), expected);
  }
}

}  // namespace
}  // namespace ancfnet
