#pragma once
#include <chrono>
/// A long computation asks, now and then, whether its caller wants it stopped: the Python module
/// sets a hook that checks for Ctrl-C (Python runs its signal handlers only when asked, and a
/// computation that holds no GIL is not interrupted otherwise). The CLI sets none: SIGINT ends
/// the process as usual.
namespace kinergy {

/// What a hook throws to stop a computation. Not a std::exception, so that no handler of
/// kinergy's that turns a failed evaluation into "no value" (catch (const std::exception&)) takes
/// it for one: it unwinds to the caller that set the hook (every resource of kinergy's is held by
/// an object that frees it).
struct Interrupted {};

/// Called by poll_interrupt(); it throws Interrupted to stop the computation.
using InterruptHook = void (*)();

/// Set (or clear, with nullptr) the hook for every thread, called at most once per `interval` on
/// each thread (0: at every poll, as the tests use it). Set before computations start.
void set_interrupt_hook(InterruptHook hook, std::chrono::milliseconds interval = std::chrono::milliseconds(50));

/// Call the hook, if one is set, when `interval` has passed on this thread since it was last
/// called (a read of a monotonic clock otherwise: cheap enough for each step of a loop).
void poll_interrupt();

}  // namespace kinergy
