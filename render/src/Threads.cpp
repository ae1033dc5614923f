#include "marbler/Threads.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <algorithm>
#include <cstdint>
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

RowLoop::RowLoop(int first, int last, int threads, const RenderControl* control)
    : mLast(last)
    , mTotal(std::max(1, last - first))
    , mWorkers(workerCount(threads, last - first))
    , mControl(control)
    , mNext(first) {}

bool RowLoop::next(int& row) {
    if (mStop.load(std::memory_order_relaxed)) return false;
    if (mControl && mControl->cancelled()) {
        mStop = true;
        return false;
    }
    row = mNext.fetch_add(1);
    return row < mLast;
}

void RowLoop::done() {
    if (!mControl || !mControl->progress) return;
    std::lock_guard lock(mProgressMutex);
    ++mDone;
    const int permille = static_cast<int>(std::int64_t(mDone) * 1000 / mTotal);
    if (permille == mLastPermille && mDone != mTotal) return;
    mLastPermille = permille;
    mControl->progress(double(mDone) / mTotal);
}

void RowLoop::run(const std::function<void()>& worker) {
    runOnThreads(mWorkers, mStop, worker);
    if (mControl && mControl->cancelled()) throw Cancelled();
}

} // namespace marbler
