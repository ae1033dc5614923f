#pragma once
/// Work spread over the machine's cores: the one thread loop of the renderers (rows, ink
/// outlines) and of breeding (looks, features). Each item is computed alone, so the order the
/// threads take them in never changes what they give: renders and bred children do not depend
/// on the number of cores.

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstddef>
#include <functional>

namespace marbler {

/// Runs `work` on `threads` threads (at least 1), the calling thread among them, and waits for
/// all of them. When one throws, `stop` is raised so the others can return early (`work` checks
/// it between items), and the first exception is rethrown here once every thread has returned.
void runOnThreads(int threads, std::atomic<bool>& stop, const std::function<void()>& work);

/// The workers for `items` items under a `threads` setting (0: every core): 1 to `items`.
int workerCount(int threads, int items);

/// Calls work(i) once for every i below `count`, on workerCount(threads, count) threads that
/// take the next index from a counter. When a call throws, the others stop after their current
/// item and the first exception is rethrown here.
template <class Work> void forEachOnCores(std::size_t count, const Work& work, int threads = 0) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    const int items = static_cast<int>(std::min<std::size_t>(count, INT_MAX));
    runOnThreads(workerCount(threads, items), stop, [&] {
        for (std::size_t i = next++; i < count && !stop; i = next++)
            work(i);
    });
}

} // namespace marbler
