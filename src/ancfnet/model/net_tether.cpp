#include "ancfnet/model/net_tether.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "ancfnet/common/error.hpp"
#include "ancfnet/model/builder_checks.hpp"
#include "ancfnet/model/net_builder.hpp"

namespace ancfnet {
namespace {

Index NearestKnot(const std::vector<Vector3d>& knots, const Vector3d& point) {
  Index nearest = 0;
  for (Index i = 1; i < static_cast<Index>(knots.size()); ++i)
    if ((knots[i] - point).norm() < (knots[nearest] - point).norm()) nearest = i;
  return nearest;
}

// A cable from the point mass `from` (sharing its position) to knot `knot` of the net.
void AddLineToKnot(ModelBuilder& builder, const NetSpec& net, const std::string& name,
                   const std::string& from, const Vector3d& from_position,
                   const Vector3d& knot_position, Index knot, int elements,
                   const CableProperties& properties, double natural_length,
                   double breaking_force) {
  const bool ideal = net.knot_model == KnotModel::kIdeal;
  builder.AddCable({.name = name,
                    .start = from_position,
                    .end = knot_position,
                    .num_elements = elements,
                    .properties = properties,
                    .natural_length = natural_length,
                    .start_knot = from,
                    .end_knot = ideal ? KnotName(net.name, knot) : "",
                    .breaking_force = breaking_force});
  builder.SetInitialVelocity(name, net.velocity);
  if (!ideal)
    builder.AddSpringDamper(name + ".end", {KnotName(net.name, knot)}, {name, 1.0}, net.link_law,
                            0.0);
}

void Validate(const NetSpec& net, const TetherSpec& tether) {
  if (tether.elements < 1 || tether.bridle_elements < 1)
    throw InputError("a tether and its bridle lines need at least 1 element each");
  if (!tether.chaser.allFinite() || !tether.chaser_velocity.allFinite())
    throw InputError("the chaser's position and velocity must be finite");
  if (!(tether.natural_length >= 0.0 && std::isfinite(tether.natural_length)))
    throw InputError(
        fmt::format("tether natural length must be ≥ 0 (got {})", tether.natural_length));
  if (tether.attachment == TetherAttachment::kBridle && net.topology.corners.empty())
    throw InputError(fmt::format("net '{}' has no corners for a bridle", net.name));
  RequireBreakingForce(tether.breaking_force, "breaking force of a tether");
  if (std::isfinite(tether.breaking_force)) RequireTetherCanFail(net.knot_model, tether.attachment);
}

}  // namespace

void RequireTetherCanFail(KnotModel knot_model, TetherAttachment attachment) {
  if (knot_model != KnotModel::kCompliant || attachment != TetherAttachment::kCenter)
    throw InputError(
        "a tether can only fail when attached at the net's centre (attach: center) with compliant "
        "knots: it then comes off the knot's link (an ideal knot or a bridle apex shares its "
        "position)");
}

void AddNetTether(ModelBuilder& builder, const NetSpec& net,
                  const std::vector<Vector3d>& knot_start, const TetherSpec& tether) {
  Validate(net, tether);
  const std::string chaser = net.name + ".chaser";
  builder.AddPointMass(chaser, 0.0, tether.chaser);
  builder.FixPointMass(chaser);
  if (tether.chaser_velocity != Vector3d::Zero())
    builder.MovePointMass(chaser, tether.chaser_velocity);

  Vector3d center = Vector3d::Zero();
  for (const Vector3d& p : knot_start) center += p;
  center /= static_cast<double>(knot_start.size());
  const std::string tether_name = net.name + ".tether";
  if (tether.attachment == TetherAttachment::kCenter) {
    const Index knot = NearestKnot(knot_start, center);
    if ((knot_start[knot] - tether.chaser).norm() == 0.0)
      throw InputError("the chaser sits on the knot its tether holds");
    AddLineToKnot(builder, net, tether_name, chaser, tether.chaser, knot_start[knot], knot,
                  tether.elements, tether.properties, tether.natural_length, tether.breaking_force);
    return;
  }
  // Bridle: the apex on the axis, behind the centroid, where the farthest corner is exactly one
  // bridle length away.
  const Vector3d axis = net.axis.normalized();
  double reach = 0.0;
  for (Index corner : net.topology.corners) {
    const Vector3d d = knot_start[corner] - center;
    reach = std::max(reach, (d - d.dot(axis) * axis).norm());
  }
  if (!(tether.bridle_length > reach))
    throw InputError(fmt::format(
        "bridle lines of {} m cannot reach the packed net's corners, {} m from its axis",
        tether.bridle_length, reach));
  const Vector3d apex =
      center - std::sqrt(tether.bridle_length * tether.bridle_length - reach * reach) * axis;
  if ((apex - tether.chaser).norm() == 0.0) throw InputError("the chaser sits on the bridle apex");
  const std::string bridle = net.name + ".bridle";
  builder.AddPointMass(bridle, 0.0, apex, net.velocity);
  builder.AddCable({.name = tether_name,
                    .start = tether.chaser,
                    .end = apex,
                    .num_elements = tether.elements,
                    .properties = tether.properties,
                    .natural_length = tether.natural_length,
                    .start_knot = chaser,
                    .end_knot = bridle});
  builder.SetInitialVelocity(tether_name, net.velocity);
  for (std::size_t i = 0; i < net.topology.corners.size(); ++i) {
    const Index corner = net.topology.corners[i];
    AddLineToKnot(builder, net, fmt::format("{}{}", bridle, i), bridle, apex, knot_start[corner],
                  corner, tether.bridle_elements, tether.properties, tether.bridle_length,
                  std::numeric_limits<double>::infinity());
  }
}

}  // namespace ancfnet
