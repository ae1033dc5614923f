#include "marbler/Workers.h"

#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace marbler {

void runOnThreads(int threads, std::atomic<bool>& stop, const std::function<void()>& work) {
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto guarded = [&] {
        try {
            work();
        } catch (...) {
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::max(1, threads); ++t)
        pool.emplace_back(guarded);
    guarded();
    for (std::thread& t : pool)
        t.join();
    if (failure) std::rethrow_exception(failure);
}

int workerCount(int threads, int items) {
    const int wanted = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(wanted, 1, std::max(1, items));
}

} // namespace marbler
