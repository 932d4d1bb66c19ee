// What a pass over a mesh noticed: how many faces (or vertices) show a
// problem, and the lowest index among them, for the message and the report.
#pragma once

#include <cstddef>

namespace polymass::core {

struct Finding {
    std::size_t count = 0;
    std::size_t first = 0;  // the lowest index, when count > 0

    void record(std::size_t index) {
        if (count++ == 0 || index < first) first = index;
    }

    void merge(const Finding& other) {
        if (other.count > 0 && (count == 0 || other.first < first)) first = other.first;
        count += other.count;
    }
};

}  // namespace polymass::core
