#include "marbler/Threads.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <algorithm>
#include <mutex>

namespace marbler {

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
