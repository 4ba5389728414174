#pragma once
/// @file When contact couplings enter and leave the pattern of the iteration matrix
/// (SystemMatrix::UpdateContactCouplings, SelfContact::FindCandidates; docs/theory.md,
/// "Contact couplings that come and go").

namespace ancfnet {

/// A coupling joins the blocks of two owners (elements, point masses, bodies) whose pair may
/// touch during a step. Every change of the set of couplings changes the pattern, and the sparse
/// solver then has to order and factorise it anew; these settings trade a few more stored zeros
/// for pattern rebuilds that are rare.
struct ContactCouplingSettings {
  /// Slack s ≥ 1: whenever the pattern is rebuilt, the self-contact candidates whose gap is
  /// below s times their coupling gap g_c are coupled too, so that a pair closing in is already
  /// coupled when it needs to be. 1: only the pairs with gap < g_c (the default: a rebuild costs
  /// less than the fill that slack adds to every factorisation, docs/benchmarks.md).
  double near_factor = 1.0;
  /// Pattern updates (attempted steps) a coupling is kept after its pair was last near; < 0
  /// keeps every coupling for good (the pattern only grows).
  int keep_updates = 50;
  /// Fraction of the contact couplings that may be stale (kept longer than keep_updates) before
  /// the pattern is rebuilt only to drop them; stale couplings are always dropped when the
  /// pattern is rebuilt for a missing one.
  double max_stale_fraction = 0.5;
};

}  // namespace ancfnet
