// The one thread loop (marbler/Workers.h) of the renderers and of breeding: every item once on
// the threads asked, and a failing item stops the others and is rethrown.

#include "marbler/Workers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace marbler;

TEST(Workers, EveryItemOnceOnTheThreadsAsked) {
    std::vector<std::atomic<int>> seen(1000);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    forEachOnCores(
        seen.size(),
        [&](std::size_t i) {
            {
                std::lock_guard lock(mutex);
                threads.insert(std::this_thread::get_id());
            }
            ++seen[i];
            // Each item takes a while, so every thread gets some, however they are scheduled.
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        },
        3);
    for (std::size_t i = 0; i < seen.size(); ++i)
        EXPECT_EQ(seen[i].load(), 1) << i;
    EXPECT_EQ(threads.size(), 3u);
}

TEST(Workers, NoItemsNoCalls) {
    int calls = 0;
    forEachOnCores(0, [&](std::size_t) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(Workers, AFailingItemStopsTheOthersAndIsRethrown) {
    std::atomic<int> done{0};
    EXPECT_THROW(forEachOnCores(
                     100000,
                     [&](std::size_t i) {
                         if (i == 50) throw std::runtime_error("item 50");
                         std::this_thread::sleep_for(std::chrono::microseconds(20));
                         ++done;
                     },
                     2),
                 std::runtime_error);
    EXPECT_LT(done.load(), 100000 - 1);
}
