#pragma once
/// One worker per core: how every multi-threaded loop of the renderers shares its work (rows,
/// texel rows or ink outlines handed out by an atomic counter the work reads).

#include <atomic>
#include <functional>
#include <mutex>

namespace marbler {

struct RenderControl;

/// Runs `work` on `threads` threads (at least 1), the calling thread among them, and waits for
/// all of them. When one throws, `stop` is raised so the others can return early (`work` checks
/// it between items), and the first exception is rethrown here once every thread has returned.
void runOnThreads(int threads, std::atomic<bool>& stop, const std::function<void()>& work);

/// The workers for `items` items under a `threads` setting (0: every core): 1 to `items`.
int workerCount(int threads, int items);

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
