#include "kinergy/common/interrupt.hpp"

#include <atomic>
#include <chrono>

namespace kinergy {

namespace {
std::atomic<InterruptHook> g_hook{nullptr};
std::atomic<long long> g_interval_ms{50};
}  // namespace

void set_interrupt_hook(InterruptHook hook, std::chrono::milliseconds interval) {
  g_interval_ms.store(interval.count());
  g_hook.store(hook);
}

void poll_interrupt() {
  const InterruptHook hook = g_hook.load(std::memory_order_relaxed);
  if (!hook) return;
  using clock = std::chrono::steady_clock;
  thread_local clock::time_point last = clock::now();
  const clock::time_point now = clock::now();
  if (now - last < std::chrono::milliseconds(g_interval_ms.load(std::memory_order_relaxed))) return;
  last = now;
  hook();
}

}  // namespace kinergy
