#include "ancfnet/analysis/first_contact.hpp"

#include <cmath>

#include "ancfnet/analysis/capture_metrics.hpp"

namespace ancfnet {

FirstContactTracker::FirstContactTracker(const Model& model, const std::vector<Probe>& probes)
    : model_(model) {
  for (const Probe& probe : probes)
    if (probe.quantity == ProbeQuantity::kCapture)
      watched_.push_back({.name = probe.name, .net = probe.net, .target = probe.target});
  if (!watched_.empty()) contact_.emplace(model);
}

void FirstContactTracker::Observe(const State& state) {
  if (found_ == static_cast<int>(watched_.size())) return;
  contacts_.clear();
  contact_->SetBodyRotations(&state.body_rotation);
  contact_->CollectContacts(state.q, state.v, state.contact_history, &contacts_);
  for (Watched& w : watched_) {
    if (std::isfinite(w.time) ||
        !CalcContactCoverage(model_, model_.nets()[w.net], w.target, contacts_).in_contact)
      continue;
    w.time = state.t;
    ++found_;
  }
}

std::map<std::string, double> FirstContactTracker::times() const {
  std::map<std::string, double> times;
  for (const Watched& w : watched_)
    if (std::isfinite(w.time)) times[w.name] = w.time;
  return times;
}

void FirstContactTracker::Save(ArchiveWriter* out) const {
  std::vector<double> times;
  for (const Watched& w : watched_) times.push_back(w.time);
  out->Write(times);
}

void FirstContactTracker::Load(ArchiveReader* in) {
  std::vector<double> times;
  in->Read(&times, static_cast<std::int64_t>(watched_.size()));
  found_ = 0;
  for (std::size_t i = 0; i < watched_.size(); ++i) {
    watched_[i].time = times[i];
    if (std::isfinite(times[i])) ++found_;
  }
}

}  // namespace ancfnet
