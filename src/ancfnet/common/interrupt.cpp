#include "ancfnet/common/interrupt.hpp"

#include <atomic>

namespace ancfnet {
namespace {

std::atomic<int> pending_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

}  // namespace

void RequestInterrupt(int signal) noexcept { pending_signal.store(signal, std::memory_order_relaxed); }

int InterruptRequested() noexcept { return pending_signal.load(std::memory_order_relaxed); }

void ClearInterrupt() noexcept { pending_signal.store(0, std::memory_order_relaxed); }

}  // namespace ancfnet
