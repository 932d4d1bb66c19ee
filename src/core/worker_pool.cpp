#include "worker_pool.hpp"

#include <utility>

namespace polymass::core {

WorkerPool::WorkerPool(std::size_t thread_count, std::pmr::memory_resource* memory)
    : workers_(memory) {
    workers_.reserve(thread_count - 1);
    try {
        for (std::size_t i = 1; i < thread_count; ++i) workers_.emplace_back([this] { work(); });
    } catch (...) {
        // A thread the system would not start: join those that did start.
        stop();
        throw;
    }
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    work_arrived_.notify_all();
    for (std::thread& worker : workers_)
        if (worker.joinable()) worker.join();
}

void WorkerPool::take_tasks(std::unique_lock<std::mutex>& lock) {
    while (next_ < count_) {
        const std::size_t index = next_++;
        ++running_;
        const std::function<void(std::size_t)>& task = *task_;
        lock.unlock();
        std::exception_ptr thrown;
        try {
            task(index);
        } catch (...) {
            thrown = std::current_exception();
        }
        lock.lock();
        --running_;
        if (thrown) {
            if (!failure_) failure_ = thrown;
            next_ = count_;  // start nothing more
        }
    }
    if (running_ == 0) work_done_.notify_all();
}

void WorkerPool::work() {
    std::unique_lock<std::mutex> lock(mutex_);
    std::size_t seen = generation_;
    for (;;) {
        work_arrived_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        take_tasks(lock);
    }
}

void WorkerPool::run(std::size_t count, const std::function<void(std::size_t)>& task) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (busy_ || workers_.empty() || count <= 1) {
        lock.unlock();
        SerialTaskRunner().run(count, task);
        return;
    }
    busy_ = true;
    task_ = &task;
    count_ = count;
    next_ = 0;
    failure_ = nullptr;
    ++generation_;
    work_arrived_.notify_all();
    take_tasks(lock);
    work_done_.wait(lock, [&] { return next_ == count_ && running_ == 0; });
    busy_ = false;
    task_ = nullptr;
    count_ = 0;
    next_ = 0;
    if (std::exception_ptr failure = std::exchange(failure_, nullptr))
        std::rethrow_exception(failure);
}

}  // namespace polymass::core
