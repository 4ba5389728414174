#include "ancfnet/model/material.hpp"

#include <numbers>

namespace ancfnet {

Section MakeCircleSection(double diameter) {
  const double pi = std::numbers::pi;
  Section s;
  s.area = pi * diameter * diameter / 4.0;
  s.second_moment = pi * diameter * diameter * diameter * diameter / 64.0;
  s.radius = diameter / 2.0;
  return s;
}

Section MakeRectangleSection(double width, double height) {
  Section s;
  s.area = width * height;
  s.second_moment = width * height * height * height / 12.0;
  s.radius = 0.5 * std::max(width, height);
  return s;
}

CableProperties MakeCableProperties(const Material& material, const Section& section) {
  CableProperties p;
  p.axial_stiffness = material.youngs_modulus * section.area;
  p.bending_stiffness = material.youngs_modulus * section.second_moment;
  p.mass_per_length = material.density * section.area;
  p.axial_damping_time = material.axial_damping_time;
  p.bending_damping_time = material.bending_damping_time;
  p.radius = section.radius;
  return p;
}

CableProperties MakeRopeProperties(const Material& material, const Section& section) {
  CableProperties p = MakeCableProperties(material, section);
  p.tension_only = true;
  p.rope_smoothing_strain = kDefaultRopeSmoothingStrain;
  p.bending_model = BendingModel::kSecondDerivative;
  return p;
}

}  // namespace ancfnet
