#pragma once
/// One worker per core for the renderers' rows (image rows, texel rows), with progress and
/// cancel, over marbler/Workers.h's thread loop.

#include "marbler/Workers.h"

#include <atomic>
#include <functional>
#include <mutex>

namespace marbler {

struct RenderControl;

/// The one row loop of the renderers (the CPU renderer, the texture baker, the mesh shader over
/// a G-buffer): rows handed out one at a time by an atomic counter to one worker per core (or
/// the `threads` setting), with cancellation and progress. A worker makes its own buffers, then
///     for (int row; rows.next(row);) { ...; rows.done(); }
/// and run() starts the workers and waits for them.
class RowLoop {
public:
    /// Rows [first, last) for workerCount(threads, last - first) workers; `control` may be null.
    RowLoop(int first, int last, int threads, const RenderControl* control);
    RowLoop(const RowLoop&) = delete;
    RowLoop& operator=(const RowLoop&) = delete;

    /// Takes the next row; false when every row is taken, the work is cancelled or a worker
    /// failed.
    bool next(int& row);
    /// Reports a row finished: progress, at most once per 1/1000 of the rows, under one lock.
    void done();
    /// Runs `worker` on every worker thread, the calling one among them, and waits. Throws
    /// Cancelled when cancelled, else rethrows the first exception a worker threw.
    void run(const std::function<void()>& worker);

    int workers() const { return mWorkers; }

private:
    int mLast, mTotal, mWorkers;
    const RenderControl* mControl;
    std::atomic<int> mNext;
    std::atomic<bool> mStop{false};
    std::mutex mProgressMutex;
    int mDone = 0, mLastPermille = -1;
};

} // namespace marbler
