#include "ancfnet/model/net_builder.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ancfnet/common/error.hpp"

namespace ancfnet {
namespace {

Vector3d Centroid(const std::vector<Vector3d>& points) {
  Vector3d sum = Vector3d::Zero();
  for (const Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

void Validate(const NetSpec& spec) {
  if (spec.name.empty()) throw InputError("a net needs a non-empty name");
  if (spec.elements_per_thread < 1)
    throw InputError(
        fmt::format("a thread needs at least 1 element (got {})", spec.elements_per_thread));
  if (!(spec.natural_length_ratio > 0.0))
    throw InputError(
        fmt::format("natural length ratio must be > 0 (got {})", spec.natural_length_ratio));
  if (!(spec.packing_ratio > 0.0 && spec.packing_ratio <= 1.0))
    throw InputError(fmt::format("packing ratio must be in (0, 1] (got {})", spec.packing_ratio));
  if (!(spec.knot_mass >= 0.0)) throw InputError("knot mass must be ≥ 0");
  if (!(spec.axis.norm() > 0.0) || !spec.axis.allFinite())
    throw InputError("a net's launch axis must be a non-zero vector");
  if (spec.knot_model == KnotModel::kCompliant && !(spec.knot_mass > 0.0))
    throw InputError("compliant knots need a knot mass > 0");
  const bool can_fail =
      std::isfinite(spec.thread_breaking_force) || std::isfinite(spec.link_breaking_force);
  if (can_fail && spec.knot_model != KnotModel::kCompliant)
    throw InputError(
        "threads and links can only fail with compliant knots: with ideal knots the threads share "
        "the knots' coordinates and could never come off");
  if (!spec.thread_designs.empty() && spec.thread_designs.size() != spec.topology.threads.size())
    throw InputError(fmt::format("net '{}' has {} threads but {} thread designs", spec.name,
                                 spec.topology.threads.size(), spec.thread_designs.size()));
  for (const ThreadDesign& design : spec.thread_designs) {
    if (design.properties && spec.beam_threads)
      throw InputError(fmt::format(
          "net '{}' has beam threads, which all take the net's material and section", spec.name));
    if (design.elements && *design.elements < 1)
      throw InputError(fmt::format("a thread needs at least 1 element (got {})", *design.elements));
    if (design.natural_length &&
        !(*design.natural_length > 0.0 && std::isfinite(*design.natural_length)))
      throw InputError(
          fmt::format("a thread's natural length must be > 0 (got {})", *design.natural_length));
  }
  if (spec.beam_threads && spec.hold_knot_sections && can_fail)
    throw InputError(fmt::format(
        "net '{}' holds the sections of its beam threads at the knots, so a failed thread would "
        "stay held: let the knots free the sections (knot_sections: free) for threads that fail",
        spec.name));
  for (const KnotMass& extra : spec.knot_masses) {
    if (extra.knot < 0 || extra.knot >= static_cast<Index>(spec.topology.knots.size()))
      throw InputError(fmt::format("no knot {} in net '{}'", extra.knot, spec.name));
    if (!(extra.mass > 0.0)) throw InputError("a mass at a knot must be > 0");
  }
}

// A section lock between every pair of beam-thread ends meeting at a knot, named
// "NET.k<i>.lock<n>".
void HoldKnotSections(ModelBuilder& builder, const NetSpec& spec) {
  std::vector<std::vector<CablePointRef>> ends(spec.topology.knots.size());
  for (std::size_t j = 0; j < spec.topology.threads.size(); ++j) {
    const auto [a, b] = spec.topology.threads[j];
    const std::string thread = ThreadName(spec.name, static_cast<Index>(j));
    ends[a].push_back({thread, 0.0});
    ends[b].push_back({thread, 1.0});
  }
  for (std::size_t k = 0; k < ends.size(); ++k) {
    int n = 0;
    for (std::size_t i = 0; i < ends[k].size(); ++i)
      for (std::size_t j = i + 1; j < ends[k].size(); ++j)
        builder.AddSectionLock(
            fmt::format("{}.lock{}", KnotName(spec.name, static_cast<Index>(k)), n++), ends[k][i],
            ends[k][j], spec.knot_section_stiffness);
  }
}

}  // namespace

std::string KnotName(const std::string& net, Index knot) {
  return fmt::format("{}.k{}", net, knot);
}

std::string ThreadName(const std::string& net, Index thread) {
  return fmt::format("{}.t{}", net, thread);
}

void AddNet(ModelBuilder& builder, const NetSpec& spec) {
  Validate(spec);
  const NetTopology& topology = spec.topology;
  const Index num_knots = static_cast<Index>(topology.knots.size());
  const Vector3d center = Centroid(topology.knots);
  std::vector<Vector3d> start(topology.knots.size());
  std::vector<double> mass(topology.knots.size(), spec.knot_mass);
  std::vector<Vector3d> velocity(topology.knots.size(), spec.velocity);
  for (Index i = 0; i < num_knots; ++i)
    start[i] = center + spec.packing_ratio * (topology.knots[i] - center);
  for (const KnotMass& extra : spec.knot_masses) {
    mass[extra.knot] += extra.mass;
    velocity[extra.knot] = extra.velocity;
  }

  Net net;
  net.name = spec.name;
  net.axis = spec.axis.normalized();
  // Knot masses first: the threads are attached to them.
  for (Index i = 0; i < num_knots; ++i)
    net.knots.push_back(
        builder.AddPointMass(KnotName(spec.name, i), mass[i], start[i], velocity[i]));

  const bool ideal = spec.knot_model == KnotModel::kIdeal;
  for (std::size_t j = 0; j < topology.threads.size(); ++j) {
    const auto [a, b] = topology.threads[j];
    const std::string name = ThreadName(spec.name, static_cast<Index>(j));
    const ThreadDesign design =
        spec.thread_designs.empty() ? ThreadDesign{} : spec.thread_designs[j];
    CableSpec cable{.name = name,
                    .start = start[a],
                    .end = start[b],
                    .num_elements = design.elements.value_or(spec.elements_per_thread),
                    .properties = design.properties.value_or(spec.thread),
                    .natural_length = design.natural_length.value_or(
                        spec.natural_length_ratio * (topology.knots[b] - topology.knots[a]).norm()),
                    .breaking_force = spec.thread_breaking_force};
    if (spec.beam_threads) {
      cable.beam = spec.beam_threads;
      cable.beam->orientation = spec.axis;
    }
    if (ideal) {
      cable.start_knot = KnotName(spec.name, a);
      cable.end_knot = KnotName(spec.name, b);
    }
    const Index index = builder.AddCable(cable);
    net.threads.push_back(index);
    // The thread moves with the net (the knots' own velocities are set above).
    builder.SetInitialVelocity(name, spec.velocity);
    if (!ideal) {
      builder.AddSpringDamper(name + ".start", {KnotName(spec.name, a)}, {name, 0.0}, spec.link_law,
                              0.0, spec.link_breaking_force);
      builder.AddSpringDamper(name + ".end", {KnotName(spec.name, b)}, {name, 1.0}, spec.link_law,
                              0.0, spec.link_breaking_force);
    }
  }
  if (spec.beam_threads && spec.hold_knot_sections) HoldKnotSections(builder, spec);
  if (spec.tether) AddNetTether(builder, spec, start, *spec.tether);
  // The threads' velocities above also set the shared knot coordinates of ideal knots.
  for (Index i = 0; i < num_knots; ++i)
    builder.SetPointMassVelocity(KnotName(spec.name, i), velocity[i]);
  for (Index knot : topology.perimeter) net.perimeter.push_back(net.knots[knot]);
  for (Index knot : topology.corners) net.corners.push_back(net.knots[knot]);
  builder.AddNetDescription(net);
}

}  // namespace ancfnet
