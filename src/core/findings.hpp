// What a pass over a mesh noticed: how many faces (or vertices) show a
// problem, and the lowest few indices among them, for the message and the
// report.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace polymass::core {

// How many locations of each finding are kept: enough to see a pattern (a
// hole's rim, a row of flipped faces), few enough to keep a finding small.
inline constexpr std::size_t kKeptLocations = 8;

// How many face pairs of a kind (crossing, touching) are counted: past that
// the count is a lower bound (surface_contacts.cpp says why).
inline constexpr std::size_t kMostCountedPairs = 2048;

struct Finding {
    std::size_t count = 0;
    std::array<std::size_t, kKeptLocations> lowest{};  // ascending; the first kept() are set

    std::size_t kept() const { return std::min(count, kKeptLocations); }
    std::size_t first() const { return lowest[0]; }  // when count > 0

    // Indices are recorded once each, in any order.
    void record(std::size_t index) {
        std::size_t slot = kept();
        ++count;
        if (slot == kKeptLocations) {
            if (index >= lowest[kKeptLocations - 1]) return;
            --slot;
        }
        for (; slot > 0 && lowest[slot - 1] > index; --slot) lowest[slot] = lowest[slot - 1];
        lowest[slot] = index;
    }

    void merge(const Finding& other) {
        const std::size_t total = count + other.count;
        for (std::size_t i = 0; i < other.kept(); ++i) record(other.lowest[i]);
        count = total;
    }
};

// Pairs of faces (or shells), each pair (low, high), counted once.
struct PairFinding {
    std::size_t count = 0;
    std::array<std::array<std::uint64_t, 2>, kKeptLocations> lowest{};  // ascending
    // False when counting stopped early (surface_contacts.cpp: a count past
    // kMostCountedPairs costs a test per pair and tells nothing more): count
    // is then a lower bound; lowest stays exact, but where the search ended
    // at the stop of the crossing pairs (SearchEnd): then both kinds hold
    // what the search found until there.
    bool complete = true;

    std::size_t kept() const { return std::min(count, kKeptLocations); }
    const std::array<std::uint64_t, 2>& first() const { return lowest[0]; }  // when count > 0

    // From pairs sorted ascending with no repeats.
    template <class SortedPairs>
    static PairFinding of(const SortedPairs& pairs) {
        PairFinding finding;
        finding.count = pairs.size();
        for (std::size_t i = 0; i < finding.kept(); ++i) finding.lowest[i] = pairs[i];
        return finding;
    }
};

}  // namespace polymass::core
