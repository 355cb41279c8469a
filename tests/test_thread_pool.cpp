// SPDX-License-Identifier: MIT
// The CPU renderer's thread pool (src/core/thread_pool.hpp): every index of a
// job runs exactly once, on a thread of the pool, whatever the counts; the
// first exception comes back to the caller and the pool stays usable.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/thread_pool.hpp"

namespace {

TEST(ThreadPool, EveryIndexRunsExactlyOnceOnAThreadOfThePool) {
    for (const int threads : {1, 2, 3, 5}) {
        litkit::ThreadPool pool(threads);
        ASSERT_EQ(pool.size(), threads);
        // Fewer indices than threads, as many, a few more, and many; twice
        // each, so that a second job on the same pool starts afresh.
        for (const std::size_t count :
             {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{5},
              std::size_t{7}, std::size_t{68}, std::size_t{1000}}) {
            for (int round = 0; round < 2; ++round) {
                const auto runs = std::make_unique<std::atomic<int>[]>(count + 1);
                std::atomic<bool> bad_worker{false};
                pool.parallel_for(count, [&](std::size_t index, int worker) {
                    runs[index].fetch_add(1);
                    if (worker < 0 || worker >= threads) bad_worker = true;
                });
                for (std::size_t i = 0; i < count; ++i)
                    EXPECT_EQ(runs[i].load(), 1)
                        << threads << " threads, index " << i << " of " << count;
                EXPECT_FALSE(bad_worker.load());
            }
        }
    }
}

TEST(ThreadPool, TheFirstExceptionReachesTheCallerAndThePoolGoesOn) {
    litkit::ThreadPool pool(3);
    std::atomic<int> ran{0};
    EXPECT_THROW(pool.parallel_for(500,
                                   [&](std::size_t index, int) {
                                       ++ran;
                                       if (index == 17) throw std::runtime_error("index 17");
                                   }),
                 std::runtime_error);
    EXPECT_LE(ran.load(), 500);
    // The next job runs every index again.
    std::vector<std::atomic<int>> runs(100);
    pool.parallel_for(runs.size(), [&](std::size_t index, int) { runs[index].fetch_add(1); });
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1);
}

}  // namespace

// A pool's constructor waits until each worker has started (so that a new
// thread does not sit on its creator's core until a scheduler tick): pools
// made and dropped at once, with and without a job, must neither hang nor
// lose a worker. A lost start would hang here (and ctest's time-out fails
// the test).
TEST(ThreadPool, PoolsMadeAndDroppedAtOnceStartEveryWorker) {
    for (int round = 0; round < 200; ++round) {
        const int threads = 1 + round % 4;
        litkit::ThreadPool pool(threads);
        EXPECT_EQ(pool.size(), threads);
        if (round % 2) {
            std::atomic<int> done{0};
            pool.parallel_for(8, [&](std::size_t, int) { ++done; });
            EXPECT_EQ(done.load(), 8);
        }
    }
}
