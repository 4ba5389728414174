#pragma once
/// @file The tether of a net: an ANCF cable from a chaser point (fixed, or moving at a constant
/// velocity) to the net's central knot, or to a bridle apex from which one bridle line runs to
/// each corner of the net (the set-ups of tethered net-capture studies, e.g. Benvenuto, Salvi &
/// Lavagna 2015; Botta, Sharf & Misra 2017).

#include <limits>
#include <vector>

#include "ancfnet/model/model_builder.hpp"

namespace ancfnet {

struct NetSpec;
enum class KnotModel;

enum class TetherAttachment {
  kCenter,  ///< to the knot nearest the net's centroid (the lowest index among equals)
  kBridle,  ///< to a bridle apex on the launch axis behind the net, with a line to every corner
};

struct TetherSpec {
  Vector3d chaser = Vector3d::Zero();           ///< chaser point at t = 0 (m)
  Vector3d chaser_velocity = Vector3d::Zero();  ///< its constant velocity (m/s); 0: fixed
  TetherAttachment attachment = TetherAttachment::kCenter;
  CableProperties properties;  ///< of the tether and of the bridle lines
  int elements = 4;            ///< ANCF elements of the tether, ≥ 1
  /// Natural length of the tether (m); 0: its initial length (it starts straight and unstrained);
  /// longer starts slack.
  double natural_length = 0.0;
  /// Natural length of each bridle line (m); it must exceed the packed net's largest corner
  /// distance from the axis: the apex sits on the axis behind the centroid where every line is
  /// at most that long.
  double bridle_length = 0.0;
  int bridle_elements = 1;  ///< ANCF elements per bridle line, ≥ 1
  /// Tension (N) at which the tether fails (analysis/failure.hpp): the link holding it to the
  /// net's knot breaks and the net flies free. > 0; infinite: never. A finite one needs compliant
  /// knots (the link) and attachment kCenter (a bridle's tether ends on the massless apex).
  double breaking_force = std::numeric_limits<double>::infinity();
};

/// Throws InputError unless a tether attached by `attachment` to a net with `knot_model` knots
/// can fail (TetherSpec::breaking_force): compliant knots and attachment kCenter.
void RequireTetherCanFail(KnotModel knot_model, TetherAttachment attachment);

/// Adds the tether of `net` (knots at `knot_start`, already added): point mass "NET.chaser"
/// (fixed or moving; massless), cable "NET.tether" from it, and for a bridle the massless point
/// "NET.bridle" with cables "NET.bridle<i>" to the corners in order. Ends meet the net as its
/// threads do: sharing the knot's position (ideal knots) or through a zero-length link
/// "<cable>.end" with the net's knot law (compliant knots), which breaks when the tether's
/// tension reaches its breaking force. Throws InputError for bad values.
void AddNetTether(ModelBuilder& builder, const NetSpec& net,
                  const std::vector<Vector3d>& knot_start, const TetherSpec& tether);

}  // namespace ancfnet
