#include "ancfnet/model/beam_section.hpp"

#include <gtest/gtest.h>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

TEST(BeamSection, RectangleHasSaintVenantTorsionConstantAndCowperShearCorrection) {
  const double a = 0.01;
  const BeamSection square = MakeRectangleBeamSection(a, a, 0.3);
  // β = 0.1406 for a square (Timoshenko & Goodier 1970, table of §109: 0.1406).
  EXPECT_NEAR(square.torsion_constant / std::pow(a, 4), 0.140577, 2e-6);
  EXPECT_NEAR(square.shear_correction_y, 0.849673, 1e-6);
  // b/a = 10: β → (1 − 0.630/10)/3 = 0.3123 (ibid.).
  const BeamSection thin = MakeRectangleBeamSection(10.0 * a, a, 0.3);
  EXPECT_NEAR(thin.torsion_constant / (10.0 * std::pow(a, 4)), 0.3123, 1e-4);
  EXPECT_DOUBLE_EQ(thin.second_moment_z, a * std::pow(10.0 * a, 3) / 12.0);
  EXPECT_DOUBLE_EQ(thin.second_moment_y, 10.0 * a * std::pow(a, 3) / 12.0);
}

TEST(BeamSection, RejectsPoissonRatioOutsideItsRange) {
  for (const double nu : {-1.0, 0.5, 0.7}) {
    EXPECT_THROW(MakeRectangleBeamSection(0.1, 0.1, nu), InputError) << nu;
    BeamMaterial material{.youngs_modulus = 1e9, .poisson_ratio = nu, .density = 1000.0};
    EXPECT_THROW(MakeBeamElementParameters(material, MakeRectangleBeamSection(0.1, 0.1, 0.3), 1.0),
                 InputError);
  }
}

TEST(BeamSection, RejectsSectionWithoutInertia) {
  const BeamMaterial material{.youngs_modulus = 1e9, .poisson_ratio = 0.3, .density = 1000.0};
  BeamSection section = MakeRectangleBeamSection(0.1, 0.1, 0.3);
  EXPECT_NO_THROW(MakeBeamElementParameters(material, section, 1.0));
  section.torsion_constant = 0.0;
  EXPECT_THROW(MakeBeamElementParameters(material, section, 1.0), InputError);
  section = MakeRectangleBeamSection(0.1, 0.1, 0.3);
  section.second_moment_y = 0.0;
  EXPECT_THROW(MakeBeamElementParameters(material, section, 1.0), InputError);
}

TEST(BeamSection, FrameIsRightHandedAndRejectsParallelOrientation) {
  const Vector3d axis(1.0, 1.0, 0.0);
  const BeamSectionFrame frame = MakeBeamSectionFrame(axis, Vector3d(0.0, 0.5, 2.0));
  EXPECT_NEAR(frame.d2.dot(axis), 0.0, 1e-15);
  EXPECT_NEAR(frame.d2.norm(), 1.0, 1e-15);
  EXPECT_NEAR(axis.normalized().cross(frame.d2).dot(frame.d3), 1.0, 1e-15);
  EXPECT_THROW(MakeBeamSectionFrame(axis, Vector3d(-2.0, -2.0, 0.0)), InputError);
  EXPECT_THROW(MakeBeamSectionFrame(axis, Vector3d::Zero()), InputError);
}

}  // namespace
}  // namespace ancfnet
