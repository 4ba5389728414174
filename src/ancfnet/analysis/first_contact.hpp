#pragma once
/// @file First contact times of the capture probes, found at every accepted time step rather than
/// at the output times (docs/theory.md, "Capture metrics").

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/contact/contact_point.hpp"
#include "ancfnet/forces/target_contact.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// Watches the capture probes (ProbeQuantity::kCapture) of a run: the first time t_c at which
/// each one's net touches its target (CalcContactCoverage(...).in_contact on the active contacts
/// with the rigid targets, TargetContact::CollectContacts).
class FirstContactTracker {
 public:
  /// Watches the capture probes among `probes` of `model`, which must outlive the tracker.
  FirstContactTracker(const Model& model, const std::vector<Probe>& probes);
  /// Records state.t for every probe not yet in contact whose net touches its target at `state`;
  /// called with the initial state and after each accepted step (and at static load steps). Does
  /// no work once every probe has touched.
  void Observe(const State& state);
  /// Capture probe name → t_c (s); a probe whose net never touched is absent.
  std::map<std::string, double> times() const;
  /// Writes the times found so far, for a checkpoint.
  void Save(ArchiveWriter* out) const;
  /// Reads what Save wrote (for the same probes).
  void Load(ArchiveReader* in);

 private:
  struct Watched {
    std::string name;
    Index net = -1;
    Index target = -1;
    double time = std::numeric_limits<double>::infinity();  // t_c; infinite: not yet
  };
  const Model& model_;
  std::optional<TargetContact> contact_;  // only with capture probes
  std::vector<Watched> watched_;
  int found_ = 0;                       // probes that have touched
  std::vector<ContactPoint> contacts_;  // reused between calls
};

}  // namespace ancfnet
