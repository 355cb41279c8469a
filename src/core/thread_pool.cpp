// SPDX-License-Identifier: MIT
#include "core/thread_pool.hpp"

#include <exception>

namespace litkit {

ThreadPool::ThreadPool(int threads) {
    if (threads <= 0) threads = static_cast<int>(std::thread::hardware_concurrency());
    if (threads <= 0) threads = 1;
    stretches_ = std::make_unique<Stretch[]>(static_cast<std::size_t>(threads));
    workers_.reserve(static_cast<std::size_t>(threads - 1));
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { worker_loop(i); });
    // Back only once every worker has run (docs/design.md, "Threads"): Linux
    // queues a new thread on its creator's core, and while the creator
    // runs on, an idle core takes it over only at the next scheduler tick,
    // up to 4 ms later. The first job then ran on the calling thread alone
    // (the 800×600 picture's two PNG halves one after the other, 4.2 ms
    // instead of 2.1). Waiting here lets the worker run at once; asleep, it
    // is woken later on whichever core is idle.
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return started_workers_ == static_cast<int>(workers_.size()); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

// Thread w takes the indices of stretch w first, in order, then helps with
// the others' (each index is handed out once, by its stretch's counter).
// Which thread does which work thus stays the same from frame to frame
// wherever the threads keep pace, and so does where the memory a stage
// writes is cached: the vertex stage's output, for one, read by the next
// stage and written again in the next frame. Handed out to whichever thread
// came first, those lines moved between the cores' caches every frame, and
// the 261k sphere's vertex stage took longer on 2 threads than on 1
// (docs/performance.md, "Threads and caches").
void ThreadPool::run_task(const Task& task, int worker) {
    const std::size_t stretches = static_cast<std::size_t>(size());
    for (std::size_t k = 0; k < stretches; ++k) {
        Stretch& stretch = stretches_[(static_cast<std::size_t>(worker) + k) % stretches];
        for (;;) {
            const std::size_t index = stretch.next.fetch_add(1, std::memory_order_relaxed);
            if (index >= stretch.end) break;
            try {
                task.call(task.context, index, worker);
            } catch (...) {
                std::lock_guard lock(mutex_);
                if (!failure_) failure_ = std::current_exception();
                // Stop handing out work.
                for (std::size_t s = 0; s < stretches; ++s)
                    stretches_[s].next.store(stretches_[s].end, std::memory_order_relaxed);
            }
        }
    }
}

void ThreadPool::worker_loop(int worker) {
    std::size_t seen_generation = 0;
    {
        std::lock_guard lock(mutex_);
        ++started_workers_;
    }
    wake_.notify_all();
    for (;;) {
        Task task;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
            if (stopping_) return;
            seen_generation = generation_;
            // A worker waking after the job finished finds task_ cleared.
            if (!task_.call) continue;
            task = task_;
            ++busy_workers_;
        }
        run_task(task, worker);
        {
            std::lock_guard lock(mutex_);
            --busy_workers_;
        }
        done_.notify_all();
    }
}

void ThreadPool::run(std::size_t count, Trampoline call, const void* context) {
    if (count == 0) return;
    {
        std::lock_guard lock(mutex_);
        task_ = Task{call, context};
        const std::size_t stretches = static_cast<std::size_t>(size());
        for (std::size_t s = 0; s < stretches; ++s) {
            stretches_[s].next.store(count * s / stretches, std::memory_order_relaxed);
            stretches_[s].end = count * (s + 1) / stretches;
        }
        failure_ = nullptr;
        ++generation_;
    }
    wake_.notify_all();
    run_task(Task{call, context}, 0);
    std::exception_ptr failure;
    {
        std::unique_lock lock(mutex_);
        // Workers that had not woken yet find task_ cleared and skip this
        // generation; wait only for those inside run_task.
        done_.wait(lock, [&] { return busy_workers_ == 0; });
        task_ = Task{};
        failure = failure_;
    }
    if (failure) std::rethrow_exception(failure);
}

}  // namespace litkit
