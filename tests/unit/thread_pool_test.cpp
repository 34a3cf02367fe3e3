// ThreadPool::parallelFor runs every item exactly once per loop, loop after
// loop, with the caller taking part, including loops too short for every
// worker to wake up in time: a worker that wakes late must never run an item
// of a loop that is over.
#include "core/util/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace f2 {
namespace {

TEST(ThreadPool, EveryItemOnceInEveryLoop) {
    for (int threads : {2, 3, 5}) {
        ThreadPool pool(threads);
        std::vector<std::atomic<int>> runs(64);
        for (std::uint32_t loop = 0; loop < 3000; ++loop) {
            // Loops of 2..64 items, most too short for every worker to join.
            const std::uint32_t count = 2 + loop % 63;
            for (std::atomic<int>& r : runs) r.store(0, std::memory_order_relaxed);
            pool.parallelFor(count,
                             [&](std::uint32_t i) { runs[i].fetch_add(1, std::memory_order_relaxed); });
            // An item of an earlier loop run late would show as a run past `count`.
            int wrong = 0;
            for (std::uint32_t i = 0; i < runs.size(); ++i)
                wrong += runs[i].load(std::memory_order_relaxed) != (i < count ? 1 : 0);
            ASSERT_EQ(wrong, 0) << threads << " threads, loop " << loop << " of " << count << " items";
        }
    }
}

TEST(ThreadPool, ALoopSeesTheWorkOfTheOneBefore) {
    // Each loop reads what the previous one wrote: parallelFor returns only
    // when every item, on whatever thread, has finished.
    ThreadPool pool(3);
    std::vector<std::uint64_t> values(256, 1);
    for (int loop = 0; loop < 500; ++loop)
        pool.parallelFor(std::uint32_t(values.size()),
                         [&](std::uint32_t i) { values[i] = values[i] * 3 + 1; });
    std::uint64_t expected = 1;
    for (int loop = 0; loop < 500; ++loop) expected = expected * 3 + 1;
    for (std::uint64_t v : values) ASSERT_EQ(v, expected);
}

}  // namespace
}  // namespace f2
