#pragma once
/// @file Builds a net into a model from its design: knots and threads of a NetTopology
/// (model/net_topology.hpp), one ANCF cable (or beam) per thread, knots ideal (threads share the
/// knot's position coordinates) or compliant (a knot mass joined to each thread end by a
/// spring-damper, the model of the seed paper), corner masses ("bullets") and a packed initial
/// state.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ancfnet/elements/connection_law.hpp"
#include "ancfnet/model/model_builder.hpp"
#include "ancfnet/model/net_tether.hpp"
#include "ancfnet/model/net_topology.hpp"

namespace ancfnet {

enum class KnotModel {
  kIdeal,      ///< the threads meeting at a knot share its position; each keeps its own slope
  kCompliant,  ///< the knot is a point mass linked to each thread end by a spring-damper
};

/// A mass attached to a knot with an initial velocity (a bullet of a deployment study).
struct KnotMass {
  Index knot = 0;                        ///< index in the topology
  double mass = 0.0;                     ///< kg, > 0
  Vector3d velocity = Vector3d::Zero();  ///< m/s
};

/// What one thread of a net may set for itself; unset values take the net's.
struct ThreadDesign {
  std::optional<CableProperties> properties;  ///< material and section (and the rope settings)
  std::optional<int> elements;                ///< ANCF elements, ≥ 1
  std::optional<double> natural_length;       ///< m, > 0
};

struct NetSpec {
  std::string name;
  NetTopology topology;
  CableProperties thread;  ///< the same for every thread (ropes: tension_only)
  /// Set: every thread is a beam of ANCF beam elements (elements/ancf_beam.hpp) of this material
  /// and section, its d₂ along the net's axis (the orientation given here is not used), and
  /// `thread` keeps only the drawing radius and the damping times, which must be the beam
  /// material's (ModelBuilder::AddCable). Knots join threads at their positions and, with
  /// hold_knot_sections, their sections' orientations.
  std::optional<BeamCableSpec> beam_threads;
  /// Beam threads only: every pair of thread ends meeting at a knot gets a section lock
  /// (ModelBuilder::AddSectionLock), so that the knot carries torsion and bending across like a
  /// tied knot. False: a ball joint, each thread free to spin about its axis there (dynamics
  /// only, or supports of its own). Excludes threads and links that can fail.
  bool hold_knot_sections = true;
  /// Stiffness (N m/rad) of those locks; default ModelBuilder::AddSectionLock's.
  std::optional<double> knot_section_stiffness;
  int elements_per_thread = 1;
  /// Per thread of the topology (empty, or one entry per thread): its own properties, elements
  /// or natural length.
  std::vector<ThreadDesign> thread_designs;
  /// Natural length of each thread over the distance of its knots in the unpacked design: > 1
  /// starts slack, < 1 pre-tensioned.
  double natural_length_ratio = 1.0;
  KnotModel knot_model = KnotModel::kIdeal;
  double knot_mass = 0.0;                ///< kg per knot, ≥ 0 (> 0 for compliant knots)
  ConnectionLaw link_law;                ///< compliant knots: law of each thread-end link
  Vector3d velocity = Vector3d::Zero();  ///< initial velocity of the whole net (m/s)
  /// Packed start: knots at centroid + ratio (p − centroid), threads keeping their natural
  /// lengths (so they start slack); 1: unpacked. In (0, 1].
  double packing_ratio = 1.0;
  std::vector<KnotMass> knot_masses;  ///< bullets and other masses at knots
  Vector3d axis = Vector3d::UnitZ();  ///< launch axis (normal of the net), for the metrics
  /// Tension (N) at which a thread fails and comes off its knots; compliant knots only.
  double thread_breaking_force = std::numeric_limits<double>::infinity();
  /// Tension (N) at which a knot link fails; compliant knots only.
  double link_breaking_force = std::numeric_limits<double>::infinity();
  std::optional<TetherSpec> tether;  ///< a tether from a chaser point (model/net_tether.hpp)
};

/// Adds the net to `builder`: point masses "NAME.k<i>" for the knots, cables "NAME.t<j>" for the
/// threads, links "NAME.t<j>.start" / ".end" for compliant knots, the tether when asked
/// (AddNetTether), and the net description.
/// Throws InputError for invalid values (a thread of a compliant net needs a law, knot masses
/// must be > 0 there, ratios must be positive, beam threads take no per-thread properties).
void AddNet(ModelBuilder& builder, const NetSpec& spec);

/// Name of knot i (a point mass) and thread j (a cable) of net `net`.
std::string KnotName(const std::string& net, Index knot);
std::string ThreadName(const std::string& net, Index thread);

}  // namespace ancfnet
