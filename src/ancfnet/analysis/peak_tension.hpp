#pragma once
/// @file The largest thread and tether tensions of each capture probe's net over a whole run,
/// found at every accepted step rather than at the output times: what the summary's safety
/// factors are taken against (docs/theory.md, "Capture metrics").

#include <map>
#include <string>
#include <vector>

#include "ancfnet/analysis/probe.hpp"
#include "ancfnet/common/binary_archive.hpp"
#include "ancfnet/model/model.hpp"
#include "ancfnet/state/state.hpp"

namespace ancfnet {

/// The peaks of one net's tensions so far (N); 0 before any observation, or without a tether.
struct PeakTensions {
  double thread = 0.0;  ///< the largest thread tension (CalcMaxThreadTension)
  double tether = 0.0;  ///< the largest tension of the net's tether NET.tether
};

/// Watches the capture probes (ProbeQuantity::kCapture) of a run.
class PeakTensionTracker {
 public:
  /// Watches the capture probes among `probes` of `model`, which must outlive the tracker.
  PeakTensionTracker(const Model& model, const std::vector<Probe>& probes);
  /// Raises each probe's peaks to the tensions at `state`; called with the initial state and
  /// after each accepted step (and at static load steps).
  void Observe(const State& state);
  /// Capture probe name → the peaks observed so far.
  std::map<std::string, PeakTensions> peaks() const;
  /// Writes the peaks found so far, for a checkpoint.
  void Save(ArchiveWriter* out) const;
  /// Reads what Save wrote (for the same probes).
  void Load(ArchiveReader* in);

 private:
  struct Watched {
    std::string name;
    Index net = -1;
    Index tether = -1;  // the net's tether cable; −1: none
    PeakTensions peak;
  };
  const Model& model_;
  std::vector<Watched> watched_;
};

}  // namespace ancfnet
