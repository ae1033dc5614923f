#pragma once
/// One worker per core: how every multi-threaded loop of the renderers shares its work (rows,
/// texel rows or ink outlines handed out by an atomic counter the work reads).

#include <atomic>
#include <functional>

namespace marbler {

/// Runs `work` on `threads` threads (at least 1), the calling thread among them, and waits for
/// all of them. When one throws, `stop` is raised so the others can return early (`work` checks
/// it between items), and the first exception is rethrown here once every thread has returned.
void runOnThreads(int threads, std::atomic<bool>& stop, const std::function<void()>& work);

} // namespace marbler
