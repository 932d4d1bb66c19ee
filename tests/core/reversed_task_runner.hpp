// A TaskRunner for the core tests that runs the tasks last first: a pool may
// finish them in any order, and a pass that joins its parts in part order
// must give the same answer.
#pragma once

#include <cstddef>
#include <functional>

#include "core/task_runner.hpp"

namespace polymass_test {

class ReversedTaskRunner final : public polymass::core::TaskRunner {
public:
    void run(std::size_t count, const std::function<void(std::size_t)>& task) override {
        for (std::size_t i = count; i-- > 0;) task(i);
    }
    std::size_t concurrency() const override { return 1; }
};

}  // namespace polymass_test
