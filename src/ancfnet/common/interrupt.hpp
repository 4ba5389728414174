#pragma once
/// @file A request to stop a running analysis at the next step boundary: set by a signal handler
/// (SIGINT, SIGTERM) or by a program, polled by the time loop and the static solver between
/// steps, which then write the state reached and stop cleanly (docs/reliability.md).

namespace ancfnet {

/// Records that the analysis should stop, and why (a signal number, > 0). Async-signal-safe: a
/// store into a lock-free atomic, so it may be called from a signal handler.
void RequestInterrupt(int signal) noexcept;

/// The signal of the pending request, 0 when none.
int InterruptRequested() noexcept;

/// Forgets a pending request (before a new analysis in the same process).
void ClearInterrupt() noexcept;

}  // namespace ancfnet
