// The library's own workers: a TaskRunner that spreads the tasks of one run
// over the calling thread and thread_count - 1 threads it starts once and
// keeps, waiting, until it is destroyed (a context owns one, so the threads
// are reused across calls and joined when the context is destroyed).
//
// Which thread runs which task is left to chance; the passes that use a
// runner fix their pieces and combine them in piece order (task_runner.hpp),
// so the bits do not depend on it.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory_resource>
#include <mutex>
#include <thread>
#include <vector>

#include "task_runner.hpp"

namespace polymass::core {

class WorkerPool final : public TaskRunner {
public:
    // thread_count >= 1 counts the calling thread; 1 starts no thread.
    WorkerPool(std::size_t thread_count, std::pmr::memory_resource* memory);
    ~WorkerPool() override;
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    std::size_t thread_count() const { return workers_.size() + 1; }
    std::size_t concurrency() const override { return thread_count(); }

    // A task that calls run on the pool it runs on gets its tasks run on its
    // own thread, one after another (the workers are all taken).
    void run(std::size_t count, const std::function<void(std::size_t)>& task) override;

private:
    void work();
    void stop();  // ends and joins the workers
    // Takes tasks of the current run until none is left to start.
    void take_tasks(std::unique_lock<std::mutex>& lock);

    std::mutex mutex_;
    std::condition_variable work_arrived_;
    std::condition_variable work_done_;
    const std::function<void(std::size_t)>* task_ = nullptr;  // the current run's
    std::size_t count_ = 0;
    std::size_t next_ = 0;     // the next task to start
    std::size_t running_ = 0;  // tasks started and not yet ended
    std::size_t generation_ = 0;
    bool busy_ = false;  // a run is under way
    bool stopping_ = false;
    std::exception_ptr failure_;
    std::pmr::vector<std::thread> workers_;
};

}  // namespace polymass::core
