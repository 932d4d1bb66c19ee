// Union-find over indices whose root is always the smallest index of its set,
// so that a set is named by its first member (welding: the lowest vertex at a
// position; shells: numbered in the order of their first faces): one for a
// single thread, and one for threads joining at once (the topology's edge walk
// and the shells).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory_resource>
#include <utility>
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

// SmallestIndexSets, safe for several threads joining at once: a root
// is linked below a smaller one by compare-and-swap, and every parent is
// smaller than its child, so paths halved by a thread reading an older parent
// still lead to the root. The sets and their roots end the same whatever the
// order of the joins - the shells' numbers do not depend on the threads.
class ConcurrentSmallestIndexSets {
public:
    // parent[i] == i for every index to start with; the sets live in it.
    explicit ConcurrentSmallestIndexSets(std::uint32_t* parent) : parent_(parent) {}

    // Two steps at a time: a root and a root's child (most of what a search
    // meets once paths are halved) both end at the first test, a branch
    // that rarely goes the other way. Always inlined: the topology's walk
    // searches once a vertex, and GCC's heuristics would take it out of
    // line as that file grows (10 instructions a vertex more: callgrind).
    __attribute__((always_inline)) std::uint32_t find(std::uint32_t index) const {
        for (;;) {
            const std::uint32_t parent = load(index);
            const std::uint32_t grandparent = load(parent);
            if (grandparent == parent) return parent;
            __atomic_store_n(&parent_[index], grandparent, __ATOMIC_RELAXED);  // halving
            index = grandparent;
        }
    }
    // join(smaller, index) in one step where it can be: when index hangs
    // below `smaller` already, or is still a root of its own (a vertex met
    // for the first time) larger than `smaller`, linked straight below it.
    // Returns where the next join of the set can start, as join does. Always
    // inlined (the topology's walk joins each edge's ends, 1.5 joins a
    // triangle): out of line, the call was a third of a join's instructions.
    __attribute__((always_inline)) std::uint32_t join_to(std::uint32_t smaller,
                                                         std::uint32_t index) const {
        std::uint32_t parent = load(index);
        if (parent == smaller) return smaller;
        if (parent == index && index > smaller &&
            __atomic_compare_exchange_n(&parent_[index], &parent, smaller, false, __ATOMIC_RELAXED,
                                        __ATOMIC_RELAXED))
            return smaller;
        return join(smaller, index);
    }
    // Returns the joined set's root (as it is then), which the next join with
    // the same set starts from: one search saved per join.
    std::uint32_t join(std::uint32_t a, std::uint32_t b) const {
        for (;;) {
            a = find(a);
            b = find(b);
            if (a == b) return a;
            if (a > b) std::swap(a, b);
            std::uint32_t expected = b;  // b is still a root
            if (__atomic_compare_exchange_n(&parent_[b], &expected, a, false, __ATOMIC_RELAXED,
                                            __ATOMIC_RELAXED))
                return a;
        }
    }

private:
    std::uint32_t load(std::uint32_t index) const {
        return __atomic_load_n(&parent_[index], __ATOMIC_RELAXED);
    }

    std::uint32_t* parent_;
};

}  // namespace polymass::core
