#include "ancfnet/io/net_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <unistd.h>

#include "ancfnet/io/beam_reader.hpp"
#include "ancfnet/io/connection_law_reader.hpp"
#include "ancfnet/io/slender_cables.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

// A number for both directions, or a pair [u, v].
template <typename Read>
auto ReadPair(const YamlValue& value, Read read) {
  if (!value.IsSequence()) {
    const auto both = read(value);
    return std::pair{both, both};
  }
  const std::vector<YamlValue> items = value.AsList();
  if (items.size() != 2) value.FailExpected("a number or a pair [u, v]");
  return std::pair{read(items[0]), read(items[1])};
}

// Memory a run needs per thread of a net, measured on the 40 × 40 net drop without self-contact
// (72 MB for 3 280 threads, docs/benchmarks.md): a floor, self-contact needs several times more.
constexpr double kBytesPerThread = 22e3;

// Refuses at `where` a net whose threads alone would need more memory than the machine has,
// before anything is built (a 10 000 × 10 000 net once took 9 s and 5.5 GB to fail).
void CheckNetFitsInMemory(const GridNetSpec& grid, const YamlValue& where) {
  const double threads = double(grid.meshes_u) * (grid.meshes_v + 1.0) +
                         double(grid.meshes_v) * (grid.meshes_u + 1.0);
  const double needed = threads * kBytesPerThread;
  const double available = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (available > 0.0 && needed > available)
    where.Fail(fmt::format("a net of {} × {} meshes has {:.3g} threads and would need at least "
                           "{:.3g} GB; this machine has {:.3g} GB",
                           grid.meshes_u, grid.meshes_v, threads, needed / 1e9, available / 1e9));
}

NetTopology ReadGridTopology(const YamlMap& map, bool diamond) {
  GridNetSpec grid;
  grid.diamond = diamond;
  std::tie(grid.side_u, grid.side_v) =
      ReadPair(map.Get("side"), [](const YamlValue& v) { return v.AsPositive(); });
  if (auto v = map.Find("meshes")) {
    if (map.Find("mesh_size")) v->Fail("give either meshes or mesh_size, not both");
    std::tie(grid.meshes_u, grid.meshes_v) =
        ReadPair(*v, [](const YamlValue& x) { return x.AsInt(1, 10000); });
  } else {
    const YamlValue size_value = map.Get("mesh_size");
    const double size = size_value.AsPositive();
    if (size > std::max(grid.side_u, grid.side_v))
      size_value.Fail(fmt::format("a mesh of {} m does not fit in a net of side {} m", size,
                                  std::max(grid.side_u, grid.side_v)));
    grid.meshes_u = MeshesForSize(grid.side_u, size);
    grid.meshes_v = MeshesForSize(grid.side_v, size);
  }
  CheckNetFitsInMemory(grid, map.Find("meshes") ? map.Get("meshes") : map.Get("mesh_size"));
  if (auto v = map.Find("center")) grid.center = v->AsVector3();
  if (auto v = map.Find("axis_u")) grid.axis_u = v->AsVector3();
  if (auto v = map.Find("axis_v")) grid.axis_v = v->AsVector3();
  // The grid builder checks the sides, axes and centre together: its errors name the net.
  return map.value().Locate([&] { return MakeGridNet(grid); });
}

// The material of `map`, or else of `fallback` (a thread falls back on its net).
const Material& ReadMaterial(const YamlMap& map, const YamlMap& fallback, const Library& library) {
  const YamlValue value = map.Find("material") ? map.Get("material") : fallback.Get("material");
  return Lookup(library.materials, value, "material", "known materials");
}

const Section& ReadSection(const YamlMap& map, const YamlMap& fallback, const Library& library) {
  const YamlValue value = map.Find("section") ? map.Get("section") : fallback.Get("section");
  return Lookup(library.sections, value, "section", "known sections");
}

// Thread properties of this material and section with the rope settings of `settings`
// (tension_only, rope_smoothing_strain, bending), else the net defaults.
CableProperties ReadThreadProperties(const YamlMap& settings, const Material& material,
                                     const Section& section) {
  CableProperties p = MakeRopeProperties(material, section);
  if (auto v = settings.Find("tension_only")) p.tension_only = v->AsBool();
  if (auto v = settings.Find("rope_smoothing_strain"))
    p.rope_smoothing_strain = v->AsNumberIn(0.0, 0.1);
  if (auto v = settings.Find("bending")) p.bending_model = ReadBendingModel(*v);
  return p;
}

// A thread of a graph net: [i, j], or {knots: [i, j], material, section, elements,
// natural_length} with its own values (material and section default to the net's).
std::array<Index, 2> ReadGraphThread(const YamlValue& thread, const YamlMap& net,
                                     const Library& library, ThreadDesign* design) {
  YamlValue knots = thread;
  if (thread.IsMap()) {
    const YamlMap map = thread.AsMap();
    map.CheckKeys({"knots", "material", "section", "elements", "natural_length"});
    knots = map.Get("knots");
    if (map.Find("material") || map.Find("section"))
      design->properties = ReadThreadProperties(net, ReadMaterial(map, net, library),
                                                ReadSection(map, net, library));
    if (auto v = map.Find("elements")) design->elements = v->AsInt(1, 1000);
    if (auto v = map.Find("natural_length")) design->natural_length = v->AsPositive();
  }
  const std::vector<YamlValue> ends = knots.AsList();
  if (ends.size() != 2) knots.FailExpected("a thread [knot, knot]");
  return {ends[0].AsInt(0), ends[1].AsInt(0)};
}

NetTopology ReadGraphTopology(const YamlMap& map, const Library& library,
                              std::vector<ThreadDesign>* designs) {
  std::vector<Vector3d> knots;
  for (const YamlValue& knot : map.Get("knot_positions").AsList(true))
    knots.push_back(knot.AsVector3());
  std::vector<std::array<Index, 2>> threads;
  for (const YamlValue& thread : map.Get("threads").AsList(true)) {
    designs->emplace_back();
    threads.push_back(ReadGraphThread(thread, map, library, &designs->back()));
  }
  std::vector<Index> perimeter;
  if (auto v = map.Find("perimeter"))
    for (const YamlValue& k : v->AsList()) perimeter.push_back(k.AsInt(0));
  return map.Get("threads").Locate([&] { return MakeGraphNet(knots, threads, perimeter); });
}

// bullets: {mass, speed, angle (degrees from the launch axis), knots: corners | [i, ...]}:
// each flies at `speed` tilted by `angle` from the axis towards the outside of the net.
void ReadBullets(const YamlValue& value, NetSpec* spec) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"mass", "speed", "angle", "knots"});
  const double mass = map.Get("mass").AsPositive();
  const double speed = map.Get("speed").AsNonNegative();
  const double angle = map.Find("angle") ? map.Get("angle").AsNumberIn(0.0, 90.0) : 0.0;
  std::vector<Index> knots = spec->topology.corners;
  if (auto v = map.Find("knots"); v && !(v->IsScalar() && v->AsString() == "corners")) {
    knots.clear();
    for (const YamlValue& k : v->AsList(true)) {
      const int knot = k.AsInt(0);
      if (knot >= static_cast<int>(spec->topology.knots.size())) k.Fail("no such knot in the net");
      knots.push_back(knot);
    }
  }
  Vector3d center = Vector3d::Zero();
  for (const Vector3d& knot : spec->topology.knots) center += knot;
  center /= static_cast<double>(spec->topology.knots.size());
  const Vector3d axis = spec->axis.normalized();
  const double theta = angle * std::numbers::pi / 180.0;
  for (Index knot : knots) {
    Vector3d radial = spec->topology.knots[knot] - center;
    radial -= radial.dot(axis) * axis;
    if (radial.norm() > 0.0) radial.normalize();
    spec->knot_masses.push_back(
        {knot, mass, spec->velocity + speed * (std::cos(theta) * axis + std::sin(theta) * radial)});
  }
}

// tether: {chaser, velocity, attach: center | bridle, material, section, elements, natural_length,
// bridle_length, bridle_elements, tension_only, rope_smoothing_strain, bending, breaking_force},
// of a net with `knot_model` knots.
TetherSpec ReadTether(const YamlValue& value, const Library& library, KnotModel knot_model) {
  const YamlMap map = value.AsMap();
  map.CheckKeys({"chaser", "velocity", "attach", "material", "section", "elements",
                 "natural_length", "bridle_length", "bridle_elements", "tension_only",
                 "rope_smoothing_strain", "bending", "breaking_force"});
  TetherSpec tether;
  tether.chaser = map.Get("chaser").AsVector3();
  if (auto v = map.Find("velocity")) tether.chaser_velocity = v->AsVector3();
  if (auto v = map.Find("attach"))
    tether.attachment = v->AsEnum<TetherAttachment>(
        {{"center", TetherAttachment::kCenter}, {"bridle", TetherAttachment::kBridle}});
  tether.properties =
      ReadThreadProperties(map, ReadMaterial(map, map, library), ReadSection(map, map, library));
  if (auto v = map.Find("elements")) tether.elements = v->AsInt(1, 1000);
  if (auto v = map.Find("natural_length")) tether.natural_length = v->AsPositive();
  if (tether.attachment == TetherAttachment::kBridle) {
    tether.bridle_length = map.Get("bridle_length").AsPositive();
    if (auto v = map.Find("bridle_elements")) tether.bridle_elements = v->AsInt(1, 1000);
  } else if (auto v = map.Find("bridle_length")) {
    v->Fail("bridle_length needs attach: bridle");
  }
  if (auto v = map.Find("breaking_force")) {
    tether.breaking_force = v->AsPositive();
    v->Locate([&] { RequireTetherCanFail(knot_model, tether.attachment); });
  }
  return tether;
}

// Length of the shortest thread between its knots (m); infinite without threads.
double ShortestThread(const NetTopology& topology) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& [i, j] : topology.threads)
    shortest = std::min(shortest, (topology.knots[i] - topology.knots[j]).norm());
  return shortest;
}

}  // namespace

void ReadNet(const YamlValue& item, const Library& library, ModelBuilder* builder,
             std::vector<std::string>* point_masses) {
  const YamlMap map = item.AsMap();
  const std::size_t type = map.Get("type").AsChoice({"square", "diamond", "graph"});
  std::vector<std::string_view> keys = {"name",
                                        "type",
                                        "material",
                                        "section",
                                        "elements_per_thread",
                                        "tension_only",
                                        "rope_smoothing_strain",
                                        "bending",
                                        "natural_length_ratio",
                                        "knot_model",
                                        "knot_mass",
                                        "knot_link",
                                        "velocity",
                                        "packing_ratio",
                                        "bullets",
                                        "thread_breaking_force",
                                        "link_breaking_force",
                                        "tether",
                                        "element",
                                        "knot_sections",
                                        "knot_section_stiffness"};
  if (type == 2)
    keys.insert(keys.end(), {"knot_positions", "threads", "perimeter", "axis"});
  else
    keys.insert(keys.end(), {"side", "meshes", "mesh_size", "center", "axis_u", "axis_v"});
  map.CheckKeys(keys);

  NetSpec spec;
  spec.name = map.Get("name").AsString();
  spec.topology = type == 2 ? ReadGraphTopology(map, library, &spec.thread_designs)
                            : ReadGridTopology(map, type == 1);
  if (type == 2) {
    if (auto v = map.Find("axis")) spec.axis = v->AsVector3();
  } else {
    const Vector3d u = map.Find("axis_u") ? map.Get("axis_u").AsVector3() : Vector3d::UnitX();
    const Vector3d v = map.Find("axis_v") ? map.Get("axis_v").AsVector3() : Vector3d::UnitY();
    spec.axis = u.cross(v);
  }
  const Section& section = ReadSection(map, map, library);
  if (ReadIsBeam(map)) {
    // Beam threads (io/beam_reader.hpp): the net's material and section, no rope settings.
    for (const char* key : {"tension_only", "rope_smoothing_strain", "bending"})
      if (auto v = map.Find(key))
        v->Fail(
            fmt::format("{} is for cable threads; beam threads (element: ancf_beam) are "
                        "elastic in tension and compression",
                        key));
    spec.beam_threads = ReadBeamMaterialAndSection(map, library);
    spec.thread = MakeCableProperties(ReadMaterial(map, map, library), section);
    if (auto v = map.Find("knot_sections"))
      spec.hold_knot_sections = v->AsEnum<bool>({{"held", true}, {"free", false}});
    if (auto v = map.Find("knot_section_stiffness")) {
      if (!spec.hold_knot_sections)
        v->Fail("knot_section_stiffness is for held knot sections (knot_sections: held)");
      spec.knot_section_stiffness = v->AsPositive();
    }
  } else {
    for (const char* key : {"knot_sections", "knot_section_stiffness"})
      if (auto v = map.Find(key))
        v->Fail(fmt::format(
            "{} is for beam threads (element: ancf_beam): a cable's section has no orientation",
            key));
    spec.thread = ReadThreadProperties(map, ReadMaterial(map, map, library), section);
  }
  if (auto v = map.Find("elements_per_thread")) spec.elements_per_thread = v->AsInt(1, 1000);
  CheckSlenderCable(section, ShortestThread(spec.topology),
                    fmt::format("the shortest thread of net '{}'", spec.name), map.Get("section"));
  if (auto v = map.Find("natural_length_ratio")) spec.natural_length_ratio = v->AsPositive();
  if (auto v = map.Find("knot_model"))
    spec.knot_model =
        v->AsEnum<KnotModel>({{"ideal", KnotModel::kIdeal}, {"compliant", KnotModel::kCompliant}});
  if (auto v = map.Find("knot_mass")) spec.knot_mass = v->AsNonNegative();
  if (spec.knot_model == KnotModel::kCompliant)
    spec.link_law = ReadConnectionLaw(map.Get("knot_link"));
  if (auto v = map.Find("velocity")) spec.velocity = v->AsVector3();
  if (auto v = map.Find("packing_ratio")) spec.packing_ratio = v->AsNumberIn(1e-6, 1.0);
  if (auto v = map.Find("bullets")) ReadBullets(*v, &spec);
  if (auto v = map.Find("thread_breaking_force")) spec.thread_breaking_force = v->AsPositive();
  if (auto v = map.Find("link_breaking_force")) spec.link_breaking_force = v->AsPositive();
  if (auto v = map.Find("tether")) spec.tether = ReadTether(*v, library, spec.knot_model);
  item.Locate([&] { AddNet(*builder, spec); });
  for (std::size_t k = 0; k < spec.topology.knots.size(); ++k)
    point_masses->push_back(KnotName(spec.name, static_cast<Index>(k)));
}

}  // namespace ancfnet
