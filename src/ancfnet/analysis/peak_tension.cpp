#include "ancfnet/analysis/peak_tension.hpp"

#include <algorithm>

#include "ancfnet/analysis/cable_tension.hpp"

namespace ancfnet {

PeakTensionTracker::PeakTensionTracker(const Model& model, const std::vector<Probe>& probes)
    : model_(model) {
  for (const Probe& probe : probes) {
    if (probe.quantity != ProbeQuantity::kCapture) continue;
    Watched watched{.name = probe.name, .net = probe.net};
    const std::string tether_name = model.nets()[probe.net].name + ".tether";
    for (std::size_t c = 0; c < model.cables().size(); ++c)
      if (model.cables()[c].name == tether_name) watched.tether = static_cast<Index>(c);
    watched_.push_back(watched);
  }
}

void PeakTensionTracker::Observe(const State& state) {
  for (Watched& w : watched_) {
    const Net& net = model_.nets()[w.net];
    if (!net.threads.empty())
      w.peak.thread = std::max(w.peak.thread, CalcMaxThreadTension(model_, net, state.q).tension);
    if (w.tether >= 0)
      w.peak.tether =
          std::max(w.peak.tether, CalcCableMaxTension(model_, model_.cables()[w.tether], state.q));
  }
}

std::map<std::string, PeakTensions> PeakTensionTracker::peaks() const {
  std::map<std::string, PeakTensions> peaks;
  for (const Watched& w : watched_) peaks[w.name] = w.peak;
  return peaks;
}

void PeakTensionTracker::Save(ArchiveWriter* out) const {
  std::vector<double> values;
  for (const Watched& w : watched_) values.insert(values.end(), {w.peak.thread, w.peak.tether});
  out->Write(values);
}

void PeakTensionTracker::Load(ArchiveReader* in) {
  std::vector<double> values;
  in->Read(&values, static_cast<std::int64_t>(2 * watched_.size()));
  for (std::size_t i = 0; i < watched_.size(); ++i)
    watched_[i].peak = {.thread = values[2 * i], .tether = values[2 * i + 1]};
}

}  // namespace ancfnet
