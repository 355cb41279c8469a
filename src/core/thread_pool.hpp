// SPDX-License-Identifier: MIT
// A small fixed thread pool owned by its user (no global state). Runs
// `parallel_for` jobs: indices 0..count-1 handed out one at a time, so uneven
// work (bands crowded with triangles) balances itself; each thread starts
// on its own stretch of them, the same from call to call (thread_pool.cpp).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace litkit {

class ThreadPool {
  public:
    // `threads` ≤ 0 means one per hardware thread. The calling thread works
    // too, so a pool of N threads starts N − 1 workers.
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int size() const { return static_cast<int>(workers_.size()) + 1; }

    // Calls job(index, worker) for every index in [0, count), spread over
    // all threads; `worker` in [0, size()) names the thread, so a job can use
    // per-thread scratch memory. Returns when all are done; the first
    // exception a job throws is rethrown here. `job` is called through a
    // plain pointer (no std::function), so a call allocates nothing.
    template <class Job>
    void parallel_for(std::size_t count, Job&& job) {
        using Callable = std::remove_reference_t<Job>;
        run(
            count,
            [](const void* context, std::size_t index, int worker) {
                (*static_cast<Callable*>(const_cast<void*>(context)))(index, worker);
            },
            std::addressof(job));
    }

  private:
    using Trampoline = void (*)(const void* context, std::size_t index, int worker);
    struct Task {
        Trampoline call = nullptr;
        const void* context = nullptr;
    };
    void run(std::size_t count, Trampoline call, const void* context);
    void worker_loop(int worker);
    void run_task(const Task& task, int worker);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    Task task_;  // call == nullptr: no job under way
    // The indices of the job under way in size() stretches, one per thread
    // to start with; a line each, so that threads taking from their own do
    // not contend.
    struct alignas(64) Stretch {
        std::atomic<std::size_t> next{0};
        std::size_t end = 0;
    };
    std::unique_ptr<Stretch[]> stretches_;
    std::size_t generation_ = 0;
    int busy_workers_ = 0;
    int started_workers_ = 0;  // workers that have begun worker_loop
    bool stopping_ = false;
    std::exception_ptr failure_;
};

}  // namespace litkit
