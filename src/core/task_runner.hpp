// How core/ runs independent pieces of work - the blocks of faces of one
// mesh, the items of a batch - on the caller's thread or on the library's
// workers, without knowing which. A pass that uses it splits its work into
// pieces fixed by the input alone (never by the number of threads) and
// combines their results in piece order, so that every thread count gives
// the same bits.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>

namespace polymass::core {

class TaskRunner {
public:
    virtual ~TaskRunner() = default;
    // Calls task(i) once for each i in [0, count) and returns when all have
    // returned. Tasks may run at the same time, in any order; each must write
    // only its own results. An exception thrown by a task is rethrown here
    // (the first one, after every started task has ended).
    virtual void run(std::size_t count, const std::function<void(std::size_t)>& task) = 0;
    // How many tasks may run at the same time: a pass that cuts its work by
    // this count, rather than in fixed blocks, must give the same result for
    // every count.
    virtual std::size_t concurrency() const = 0;
};

// Runs the tasks one after another on the calling thread.
class SerialTaskRunner final : public TaskRunner {
public:
    void run(std::size_t count, const std::function<void(std::size_t)>& task) override {
        for (std::size_t i = 0; i < count; ++i) task(i);
    }
    std::size_t concurrency() const override { return 1; }
};

// How many items a block of a pass cut in fixed blocks holds: enough work a
// task to outweigh handing it out, and a million items make blocks enough to
// share among threads.
inline constexpr std::size_t kItemsPerBlock = std::size_t{1} << 16;

// How many blocks of block_size items `count` items make (the last maybe shorter).
inline std::size_t block_count(std::size_t count, std::size_t block_size) {
    return (count + block_size - 1) / block_size;
}

// Calls visit(block, begin, end) for each block [begin, end) of [0, count),
// blocks of block_size run as tasks on `tasks`: for passes that carry state
// from one item of a block to the next.
template <class Visit>
void for_each_block(std::size_t count, std::size_t block_size, TaskRunner& tasks,
                    const Visit& visit) {
    tasks.run(block_count(count, block_size), [&](std::size_t block) {
        visit(block, block * block_size, std::min(count, (block + 1) * block_size));
    });
}

// Calls visit(block, i) for each i in [0, count), in blocks of block_size
// (block i / block_size) run as tasks on `tasks`, each block's items in
// ascending order: for passes that keep results per block and join them in
// block order.
template <class Visit>
void for_each_in_numbered_blocks(std::size_t count, std::size_t block_size, TaskRunner& tasks,
                                 const Visit& visit) {
    for_each_block(count, block_size, tasks,
                   [&](std::size_t block, std::size_t begin, std::size_t end) {
                       for (std::size_t i = begin; i < end; ++i) visit(block, i);
                   });
}

// Calls visit(i) for each i in [0, count), in blocks of block_size run as
// tasks on `tasks`: for passes whose items are independent of one another.
template <class Visit>
void for_each_in_blocks(std::size_t count, std::size_t block_size, TaskRunner& tasks,
                        const Visit& visit) {
    for_each_in_numbered_blocks(count, block_size, tasks,
                                [&](std::size_t, std::size_t i) { visit(i); });
}

}  // namespace polymass::core
