// The one row loop (marbler/Threads.h) the CPU renderer, the texture baker and the mesh shader
// share: every row once, the threads setting honoured, progress to 1, cancel stops it.

#include "marbler/Threads.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

using namespace marbler;

TEST(RowLoop, EveryRowOnceOnTheThreadsAsked) {
    RowLoop rows(3, 203, 3, nullptr);
    EXPECT_EQ(rows.workers(), 3);
    std::vector<std::atomic<int>> seen(203);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    rows.run([&] {
        {
            std::lock_guard lock(mutex);
            threads.insert(std::this_thread::get_id());
        }
        for (int row; rows.next(row);) {
            ++seen[std::size_t(row)];
            std::this_thread::yield();
            rows.done();
        }
    });
    for (int row = 0; row < 203; ++row)
        EXPECT_EQ(seen[std::size_t(row)].load(), row >= 3 ? 1 : 0) << row;
    EXPECT_EQ(threads.size(), 3u);
}

TEST(RowLoop, WorkerCountFollowsTheSetting) {
    EXPECT_EQ(workerCount(5, 100), 5);
    EXPECT_EQ(workerCount(5, 2), 2) << "never more workers than rows";
    EXPECT_EQ(workerCount(0, 1000000), std::max(1, int(std::thread::hardware_concurrency())));
    EXPECT_EQ(workerCount(0, 0), 1);
}

TEST(RowLoop, ProgressReachesOneAndCancelThrows) {
    std::vector<double> reported;
    RenderControl control;
    control.progress = [&](double f) { reported.push_back(f); };
    RowLoop rows(0, 10, 1, &control);
    rows.run([&] {
        for (int row; rows.next(row);)
            rows.done();
    });
    ASSERT_FALSE(reported.empty());
    EXPECT_DOUBLE_EQ(reported.back(), 1.0);

    std::atomic<bool> cancel{false};
    RenderControl stopping;
    stopping.cancel = &cancel;
    RowLoop cancelled(0, 1000, 2, &stopping);
    std::atomic<int> done{0};
    EXPECT_THROW(cancelled.run([&] {
        for (int row; cancelled.next(row);) {
            if (++done == 10) cancel = true;
        }
    }),
                 Cancelled);
    EXPECT_LT(done.load(), 1000);
}

TEST(RowLoop, AFailingWorkerStopsTheOthersAndIsRethrown) {
    RowLoop rows(0, 100000, 2, nullptr);
    std::atomic<int> done{0};
    EXPECT_THROW(rows.run([&] {
        for (int row; rows.next(row);) {
            if (row == 50) throw RuntimeFailure("row 50");
            // Each row takes a while, so the other worker cannot finish all of them in the
            // moment between the throw and the loop's stop, however the threads are scheduled.
            std::this_thread::sleep_for(std::chrono::microseconds(20));
            ++done;
        }
    }),
                 RuntimeFailure);
    EXPECT_LT(done.load(), 100000 - 1);
}
