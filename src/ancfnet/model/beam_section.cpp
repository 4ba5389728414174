#include "ancfnet/model/beam_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

void RequirePoissonRatio(double nu) {
  if (!(nu > -1.0 && nu < 0.5))
    throw InputError(fmt::format("Poisson's ratio {} is outside (-1, 0.5)", nu));
}

void RequirePositive(double value, const char* name) {
  if (!(value > 0.0)) throw InputError(fmt::format("beam {} must be > 0, got {}", name, value));
}

// Saint-Venant torsion constant of an a × c rectangle, a ≥ c (the series converges like n⁻⁵;
// 20 odd terms reach machine precision).
double RectangleTorsionConstant(double a, double c) {
  double sum = 0.0;
  for (int n = 1; n < 40; n += 2)
    sum += std::tanh(n * std::numbers::pi * a / (2.0 * c)) / std::pow(n, 5);
  return a * c * c * c / 3.0 * (1.0 - 192.0 / std::pow(std::numbers::pi, 5) * (c / a) * sum);
}

}  // namespace

BeamSection MakeRectangleBeamSection(double height, double width, double poisson_ratio) {
  RequirePositive(height, "section height");
  RequirePositive(width, "section width");
  RequirePoissonRatio(poisson_ratio);
  const double k = 10.0 * (1.0 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio);
  return {.area = height * width,
          .second_moment_y = height * width * width * width / 12.0,
          .second_moment_z = width * height * height * height / 12.0,
          .torsion_constant =
              RectangleTorsionConstant(std::max(height, width), std::min(height, width)),
          .shear_correction_y = k,
          .shear_correction_z = k};
}

BeamSection MakeCircleBeamSection(double diameter, double poisson_ratio) {
  RequirePositive(diameter, "section diameter");
  RequirePoissonRatio(poisson_ratio);
  const double d2 = diameter * diameter;
  const double second_moment = std::numbers::pi * d2 * d2 / 64.0;
  const double k = 6.0 * (1.0 + poisson_ratio) / (7.0 + 6.0 * poisson_ratio);
  return {.area = std::numbers::pi * d2 / 4.0,
          .second_moment_y = second_moment,
          .second_moment_z = second_moment,
          .torsion_constant = 2.0 * second_moment,
          .shear_correction_y = k,
          .shear_correction_z = k};
}

BeamElementParameters MakeBeamElementParameters(const BeamMaterial& material,
                                                const BeamSection& section, double length) {
  RequirePositive(length, "element length");
  RequirePositive(material.youngs_modulus, "Young's modulus");
  RequirePositive(material.density, "density");
  RequirePoissonRatio(material.poisson_ratio);
  for (const double tau : {material.axial_damping_time, material.bending_damping_time})
    if (!(tau >= 0.0 && std::isfinite(tau)))
      throw InputError(fmt::format("a damping time must be ≥ 0 (got {})", tau));
  RequirePositive(section.area, "section area");
  RequirePositive(section.second_moment_y, "second moment of area I_y");
  RequirePositive(section.second_moment_z, "second moment of area I_z");
  RequirePositive(section.torsion_constant, "torsion constant J");
  for (const double k : {section.shear_correction_y, section.shear_correction_z})
    if (!(k > 0.0 && k <= 1.0))
      throw InputError(fmt::format("beam shear correction factor {} is outside (0, 1]", k));
  const double e = material.youngs_modulus;
  const double g = e / (2.0 * (1.0 + material.poisson_ratio));
  const double rho = material.density;
  return {.length = length,
          .axial_stiffness = e * section.area,
          .shear_stiffness_y = section.shear_correction_y * g * section.area,
          .shear_stiffness_z = section.shear_correction_z * g * section.area,
          .torsional_stiffness = g * section.torsion_constant,
          .bending_stiffness_y = e * section.second_moment_y,
          .bending_stiffness_z = e * section.second_moment_z,
          .section_normal_stiffness = e * section.area,
          .section_shear_stiffness = g * section.area,
          .mass_per_length = rho * section.area,
          .rotary_inertia_y = rho * section.second_moment_y,
          .rotary_inertia_z = rho * section.second_moment_z,
          .axial_damping_time = material.axial_damping_time,
          .bending_damping_time = material.bending_damping_time};
}

BeamSectionFrame MakeBeamSectionFrame(const Vector3d& axis, const Vector3d& orientation) {
  if (axis.norm() == 0.0 || orientation.norm() == 0.0)
    throw InputError("beam axis and orientation vector must not be zero");
  const Vector3d t = axis.normalized();
  const Vector3d n = orientation - orientation.dot(t) * t;
  if (n.norm() <= 1e-6 * orientation.norm())
    throw InputError("beam orientation vector is parallel to the beam axis");
  const Vector3d d2 = n.normalized();
  return {.d2 = d2, .d3 = t.cross(d2)};
}

}  // namespace ancfnet
