// Union-find over indices whose root is always the smallest index of its set,
// so that a set is named by its first member (welding: the lowest vertex at a
// position; shells: numbered in the order of their first faces).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory_resource>
#include <vector>

namespace polymass::core {

class SmallestIndexSets {
public:
    // parent[i] == i for every index to start with; the sets live in it.
    explicit SmallestIndexSets(std::pmr::vector<std::uint32_t>& parent) : parent_(parent) {}

    std::uint32_t find(std::uint32_t index) {
        while (parent_[index] != index) {
            parent_[index] = parent_[parent_[index]];  // path halving
            index = parent_[index];
        }
        return index;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::pmr::vector<std::uint32_t>& parent_;
};

}  // namespace polymass::core
