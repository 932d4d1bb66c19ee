#include "radix_sort.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace polymass::core {
namespace {

constexpr int digit_bits = 16;
constexpr int digit_count = 64 / digit_bits;
// The low 32 bits ascend already: a stable sort by the digits above them
// keeps that order among keys whose high bits are equal.
constexpr int lowest_digit = 32 / digit_bits;
constexpr std::size_t bucket_count = std::size_t{1} << digit_bits;

std::size_t digit(std::uint64_t key, int position) {
    return std::size_t(key >> (position * digit_bits)) & (bucket_count - 1);
}

}  // namespace

void radix_sort_high_half(std::uint64_t* first, std::uint64_t* last,
                          std::pmr::memory_resource* memory) {
    const std::size_t count = std::size_t(last - first);
    // Below a few thousand keys the histograms cost more than a comparison
    // sort; above 2^32 the 32-bit counts would overflow.
    if (count < 2048 || count > UINT32_MAX) {
        std::sort(first, last);
        return;
    }
    // All histograms in one pass over the keys.
    std::pmr::vector<std::uint32_t> counts((digit_count - lowest_digit) * bucket_count, 0, memory);
    auto histogram_of = [&](int position) {
        return &counts[(position - lowest_digit) * bucket_count];
    };
    for (const std::uint64_t* key = first; key != last; ++key)
        for (int position = lowest_digit; position < digit_count; ++position)
            ++histogram_of(position)[digit(*key, position)];

    std::pmr::vector<std::uint64_t> scratch(count, memory);
    std::uint64_t* source = first;
    std::uint64_t* target = scratch.data();
    for (int position = lowest_digit; position < digit_count; ++position) {
        std::uint32_t* histogram = histogram_of(position);
        // A digit that is the same in every key (such as the high digits of
        // small vertex numbers) leaves the order as it is.
        if (histogram[digit(*first, position)] == count) continue;
        std::uint32_t offset = 0;
        for (std::size_t bucket = 0; bucket < bucket_count; ++bucket)
            offset += std::exchange(histogram[bucket], offset);
        for (std::size_t i = 0; i < count; ++i)
            target[histogram[digit(source[i], position)]++] = source[i];
        std::swap(source, target);
    }
    if (source != first) std::copy(source, source + count, first);
}

}  // namespace polymass::core
