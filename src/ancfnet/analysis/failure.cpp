#include "ancfnet/analysis/failure.hpp"

#include <cmath>

#include "ancfnet/analysis/cable_tension.hpp"
#include "ancfnet/forces/link_forces.hpp"

namespace ancfnet {
namespace {

// Breaks link l: marks it and adds the energy it held.
void BreakLink(const Model& model, Index l, State* state, FailureCheck* check) {
  state->link_broken[l] = 1;
  ++check->broken_links;
  check->released_energy += CalcLinkEnergy(model.links()[l], state->q);
}

}  // namespace

bool CanFail(const Model& model) {
  for (const SpringDamperLink& link : model.links())
    if (std::isfinite(link.breaking_force)) return true;
  for (const Cable& cable : model.cables())
    if (std::isfinite(cable.breaking_force)) return true;
  return false;
}

FailureCheck ApplyFailures(const Model& model, State* state, std::vector<FailureEvent>* events) {
  FailureCheck check;
  const auto& links = model.links();
  for (std::size_t l = 0; l < links.size(); ++l) {
    const SpringDamperLink& link = links[l];
    if (state->link_broken[l] || !std::isfinite(link.breaking_force)) continue;
    const double tension = CalcLinkState(link, state->q, state->v).tension;
    if (tension < link.breaking_force) continue;
    BreakLink(model, static_cast<Index>(l), state, &check);
    events->push_back({state->t, link.name, tension});
  }
  const auto& cables = model.cables();
  for (std::size_t c = 0; c < cables.size(); ++c) {
    if (!std::isfinite(cables[c].breaking_force)) continue;
    const double tension = CalcCableMaxTension(model, cables[c], state->q);
    if (tension < cables[c].breaking_force) continue;
    const int before = check.broken_links;
    for (std::size_t l = 0; l < links.size(); ++l) {
      const bool holds = links[l].first_cable == static_cast<Index>(c) ||
                         links[l].second_cable == static_cast<Index>(c);
      if (holds && !state->link_broken[l]) BreakLink(model, static_cast<Index>(l), state, &check);
    }
    if (check.broken_links > before) events->push_back({state->t, cables[c].name, tension});
  }
  return check;
}

}  // namespace ancfnet
