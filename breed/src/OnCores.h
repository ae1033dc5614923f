#pragma once
/// Work spread over the machine's cores (internal to breed/). Each item is computed alone, so
/// the order the threads take them in never changes what they give: breeding stays
/// reproducible from the seed however many cores there are.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace marbler::breeddetail {

/// Calls work(i) for every i below count, on up to 16 threads (the calling one among them).
/// work must not throw: an item that can fail records it for the caller to act on.
template <class Work> void forEachOnCores(std::size_t count, const Work& work) {
    std::atomic<std::size_t> next{0};
    const auto run = [&] {
        for (std::size_t i = next++; i < count; i = next++)
            work(i);
    };
    const std::size_t cores = std::max(std::thread::hardware_concurrency(), 1u);
    const std::size_t extra = std::min({cores - 1, std::size_t(15), count > 0 ? count - 1 : 0});
    std::vector<std::thread> threads;
    threads.reserve(extra);
    for (std::size_t t = 0; t < extra; ++t)
        threads.emplace_back(run);
    run();
    for (std::thread& t : threads)
        t.join();
}

} // namespace marbler::breeddetail
