#include "ancfnet/io/beam_reader.hpp"

#include <fmt/format.h>

#include <string>

namespace ancfnet {
namespace {

// The beam section of a section map for Poisson's ratio ν: the closed forms of circle and
// rectangle (model/beam_section.hpp), or the values of a `general` section.
BeamSection ReadBeamSection(const YamlValue& value, const std::string& name, double nu) {
  const YamlMap map = value.AsMap();
  const std::size_t shape = map.Get("shape").AsChoice({"circle", "rectangle", "general"});
  // The dimensions were checked when the section was read; ν when the material was.
  if (shape == 0) return MakeCircleBeamSection(map.Get("diameter").AsPositive(), nu);
  if (shape == 1)
    return MakeRectangleBeamSection(map.Get("height").AsPositive(), map.Get("width").AsPositive(),
                                    nu);
  BeamSection section;
  section.area = map.Get("area").AsPositive();
  for (const auto& [key, field] :
       {std::pair{"second_moment_y", &section.second_moment_y},
        {"second_moment_z", &section.second_moment_z},
        {"torsion_constant", &section.torsion_constant}}) {
    const std::optional<YamlValue> v = map.Find(key);
    if (!v)
      value.Fail(fmt::format("section '{}' has no {}, which an ancf_beam needs", name, key));
    *field = v->AsPositive();
  }
  const double k = map.Find("shear_correction") ? map.Get("shear_correction").AsNumberIn(0.0, 1.0)
                                                 : 5.0 / 6.0;
  if (!(k > 0.0)) map.Get("shear_correction").Fail("a shear correction factor must be in (0, 1]");
  section.shear_correction_y = section.shear_correction_z = k;
  return section;
}

}  // namespace

std::optional<double> ReadPoissonRatio(const YamlMap& material) {
  const std::optional<YamlValue> ratio = material.Find("poisson_ratio");
  const std::optional<YamlValue> shear = material.Find("shear_modulus");
  if (ratio && shear) shear->Fail("give either poisson_ratio or shear_modulus, not both");
  if (!ratio && !shear) return std::nullopt;
  // ν = E/(2G) − 1 (isotropic elasticity).
  const double nu = ratio ? ratio->AsNumber()
                          : material.Get("youngs_modulus").AsPositive() /
                                    (2.0 * shear->AsPositive()) -
                                1.0;
  if (!(nu > -1.0 && nu < 0.5))
    (ratio ? *ratio : *shear)
        .Fail(fmt::format("Poisson's ratio must be in (-1, 0.5) (got {})", nu));
  return nu;
}

bool ReadIsBeam(const YamlMap& map) {
  const std::optional<YamlValue> element = map.Find("element");
  return element && element->AsChoice({"cable", "ancf_beam"}) == 1;
}

BeamCableSpec ReadBeamMaterialAndSection(const YamlMap& map, const Library& library) {
  const YamlValue material_key = map.Get("material");
  const YamlValue& material =
      Lookup(library.material_values, material_key, "material", "known materials");
  const std::optional<double> nu = ReadPoissonRatio(material.AsMap());
  if (!nu)
    material_key.Fail(fmt::format(
        "material '{}' has no poisson_ratio (or shear_modulus), which an ancf_beam needs",
        material_key.AsString()));
  BeamCableSpec spec;
  spec.material = {.youngs_modulus = material.AsMap().Get("youngs_modulus").AsPositive(),
                   .poisson_ratio = *nu,
                   .density = material.AsMap().Get("density").AsPositive()};
  for (const auto& [key, field] :
       {std::pair{"axial_damping_time", &spec.material.axial_damping_time},
        {"bending_damping_time", &spec.material.bending_damping_time}})
    if (auto v = material.AsMap().Find(key)) *field = v->AsNonNegative();
  const YamlValue section_key = map.Get("section");
  spec.section = ReadBeamSection(
      Lookup(library.section_values, section_key, "section", "known sections"),
      section_key.AsString(), *nu);
  return spec;
}

std::optional<BeamCableSpec> ReadBeamCable(const YamlMap& cable, const Vector3d& axis,
                                           const Library& library) {
  if (!ReadIsBeam(cable)) {
    if (auto v = cable.Find("orientation"))
      v->Fail("orientation is for beams (element: ancf_beam)");
    return std::nullopt;
  }
  BeamCableSpec spec = ReadBeamMaterialAndSection(cable, library);
  const YamlValue orientation = cable.Get("orientation");
  spec.orientation = orientation.AsVector3();
  orientation.Locate([&] { MakeBeamSectionFrame(axis, spec.orientation); });
  return spec;
}

}  // namespace ancfnet
