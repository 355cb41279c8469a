#include "cpu/thread_pool.hpp"

#include <exception>

namespace litkit {

ThreadPool::ThreadPool(int threads) {
    if (threads <= 0) threads = static_cast<int>(std::thread::hardware_concurrency());
    if (threads <= 0) threads = 1;
    workers_.reserve(static_cast<std::size_t>(threads - 1));
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { worker_loop(i); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::run_task(const Task& task, std::size_t count, int worker) {
    for (;;) {
        std::size_t index = next_index_.fetch_add(1, std::memory_order_relaxed);
        if (index >= count) return;
        try {
            task.call(task.context, index, worker);
        } catch (...) {
            std::lock_guard lock(mutex_);
            if (!failure_) failure_ = std::current_exception();
            next_index_.store(count, std::memory_order_relaxed);  // stop handing out work
        }
    }
}

void ThreadPool::worker_loop(int worker) {
    std::size_t seen_generation = 0;
    for (;;) {
        Task task;
        std::size_t count = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
            if (stopping_) return;
            seen_generation = generation_;
            // A worker waking after the job finished finds task_ cleared.
            if (!task_.call) continue;
            task = task_;
            count = job_count_;
            ++busy_workers_;
        }
        run_task(task, count, worker);
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
        job_count_ = count;
        next_index_.store(0, std::memory_order_relaxed);
        failure_ = nullptr;
        ++generation_;
    }
    wake_.notify_all();
    run_task(Task{call, context}, count, 0);
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
