#pragma once
/// @file Step-size control on the energy balance: the error the time discretisation makes in the
/// balance kinetic + strain + gravity + dissipated − work, step by step, held within a budget
/// spread evenly over the run (docs/theory.md, "Energy step control").

#include "ancfnet/analysis/energy.hpp"
#include "ancfnet/common/binary_archive.hpp"

namespace ancfnet {

/// The budget of the balance drift over a run from t₀ to t_end is η E_s, E_s the energy scale
/// (the largest kinetic + strain + |gravity| + |work| + dissipated met so far) and η the allowed
/// fraction (DynamicSettings::energy_drift). A step of size h may spend e* = η E_s h / (t_end −
/// t₀). Where contact events (impacts, a thread leaving a target) are not resolved by the step,
/// each event leaves an error ∝ h (the trapezoidal work of a force switched on or off within the
/// step) and events come at a rate set by the motion, so the error of a step is ∝ h²: its ratio
/// e/e* is ∝ h, and the next step is h e*/e, at least h/4. A step within half its budget lets the
/// step grow again. Energy lost counts as well as energy created (e = |B_{n+1} − B_n|): counting
/// only the gain let the capture demo gain 1.8 % where its budget was 0.5 %.
class EnergyStepControl {
 public:
  /// η = `drift` (0: off), over the run from t₀ = `start` to `end` (s), from the account at t₀.
  EnergyStepControl(double drift, double start, double end, const EnergyAccount& initial);
  bool enabled() const { return drift_ > 0.0; }
  /// After an accepted step of size h (s) that led to `account`: the factor (≤ 1) the next step
  /// must be cut by, 1 when the step kept to its budget.
  double Cut(double h, const EnergyAccount& account);
  /// Whether the last step spent at most half its budget, so that the step may grow.
  bool may_grow() const { return may_grow_; }
  /// Writes the energy scale and balance reached; LoadCheckpoint restores them into a control
  /// made with the same drift, start and end.
  void SaveCheckpoint(ArchiveWriter* out) const;
  void LoadCheckpoint(ArchiveReader* in);

 private:
  double drift_;
  double duration_;
  double scale_;
  double balance_;
  bool may_grow_ = true;
};

}  // namespace ancfnet
