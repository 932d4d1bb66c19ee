#include "welding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// Identity for every vertex, and the used vertices in index order.
template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> identity_map(const MeshView<Scalar, Index>& mesh,
                                             const MeshScan& scan,
                                             std::pmr::vector<std::uint32_t>& used,
                                             std::pmr::memory_resource* memory) {
    const std::size_t addressable = scan.used.size() * 64;
    std::pmr::vector<std::uint32_t> representative(std::min(mesh.vertex_count, addressable),
                                                   memory);
    used.reserve(scan.used_vertex_count);
    for (std::size_t vertex = 0; vertex < representative.size(); ++vertex) {
        representative[vertex] = std::uint32_t(vertex);
        if (scan.is_used(vertex)) used.push_back(std::uint32_t(vertex));
    }
    return representative;
}

// The bits of a coordinate, +0 for -0 (the same position).
std::uint64_t position_bits(double value) {
    value += 0.0;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// A 64-bit mix of a position's three bit patterns (splitmix64's finaliser).
std::uint64_t position_hash(const std::array<std::uint64_t, 3>& bits) {
    std::uint64_t h = bits[0] * 0x9E3779B97F4A7C15ull ^ bits[1] * 0xC2B2AE3D27D4EB4Full ^
                      bits[2] * 0x165667B19E3779F9ull;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    return h;
}

// One hashing pass over the used vertices in index order: the first vertex
// met at a position (the lowest index) enters the table and names every
// later one with the same bits. The table holds only distinct positions (a
// triangle soup asks about each corner, but has a sixth as many vertices),
// in open addressing with linear probing, at most half full. Each slot keeps
// the vertex with the high half of its hash, so that a probe reads another
// vertex's coordinates only when the halves agree (almost only for a copy),
// and the slot of a vertex a few ahead is prefetched: the table outgrows the
// caches, and waiting on it was the pass's cost. Comparing bits rather than
// values is exact welding for finite coordinates and still defined for NaN
// (copies of one NaN are one vertex), which sorting is not.
template <class Scalar, class Index>
void weld_exact(const MeshView<Scalar, Index>& mesh, const std::pmr::vector<std::uint32_t>& used,
                std::pmr::vector<std::uint32_t>& representative,
                std::pmr::memory_resource* memory) {
    using Bits = std::array<std::uint64_t, 3>;
    const auto bits_of = [&](std::uint32_t vertex) {
        const Eigen::Vector3d p = mesh.positions[vertex];
        return Bits{position_bits(p.x()), position_bits(p.y()), position_bits(p.z())};
    };
    // A slot: the hash's high half, then the vertex index + 1 (0: empty).
    const auto slot_of = [](std::uint64_t hash, std::uint32_t vertex) {
        return (hash & 0xFFFFFFFF00000000ull) | (std::uint64_t(vertex) + 1);
    };
    std::pmr::vector<std::uint64_t> slots(std::size_t(1) << 12, 0, memory);
    std::size_t distinct = 0;
    const auto place = [&](std::uint64_t entry, std::uint64_t hash) {
        const std::size_t mask = slots.size() - 1;
        std::size_t slot = hash & mask;
        while (slots[slot] != 0) slot = (slot + 1) & mask;
        slots[slot] = entry;
    };
    // The hashes of the next kAhead vertices, by u % kAhead.
    constexpr std::size_t kAhead = 16;
    std::array<std::uint64_t, kAhead> ahead{};
    const auto hash_ahead = [&](std::size_t u) {
        if (u >= used.size()) return;
        const std::uint64_t hash = position_hash(bits_of(used[u]));
        ahead[u % kAhead] = hash;
        __builtin_prefetch(&slots[hash & (slots.size() - 1)]);
    };
    for (std::size_t u = 0; u < kAhead; ++u) hash_ahead(u);
    for (std::size_t u = 0; u < used.size(); ++u) {
        const std::uint32_t vertex = used[u];
        const Bits bits = bits_of(vertex);
        const std::uint64_t hash = ahead[u % kAhead];
        hash_ahead(u + kAhead);
        const std::uint64_t tag = hash & 0xFFFFFFFF00000000ull;
        const std::size_t mask = slots.size() - 1;
        std::size_t slot = hash & mask;
        for (; slots[slot] != 0; slot = (slot + 1) & mask) {
            const std::uint64_t entry = slots[slot];
            if ((entry & 0xFFFFFFFF00000000ull) != tag) continue;
            const Bits held = bits_of(std::uint32_t(entry) - 1);
            if (held[0] == bits[0] && held[1] == bits[1] && held[2] == bits[2]) break;
        }
        if (slots[slot] != 0) {
            representative[vertex] = std::uint32_t(slots[slot]) - 1;
            continue;
        }
        slots[slot] = slot_of(hash, vertex);
        if (2 * ++distinct > slots.size()) {
            std::pmr::vector<std::uint64_t> held(std::move(slots));
            slots = std::pmr::vector<std::uint64_t>(2 * held.size(), 0, memory);
            for (const std::uint64_t entry : held)
                if (entry != 0) place(entry, position_hash(bits_of(std::uint32_t(entry) - 1)));
        }
    }
}

// A grid of cells `distance` wide: vertices in one cell are within `distance`
// of each other in every coordinate (up to rounding), so they are one; vertices
// in adjacent cells are one when any pair across them is that close. A hash
// of the occupied cells numbers them as they are first met and a counting pass
// groups each cell's vertices; each cell then looks up the 13 neighbours of
// `offsets` in the hash (the other 13 meet it from their side). The sets do
// not depend on the order cells are met in. The cost is O(n) unless many
// distinct vertices crowd two adjacent cells without touching (then it is
// their product).
template <class Scalar, class Index>
void weld_within(const MeshView<Scalar, Index>& mesh, const MeshScan& scan, double distance,
                 const std::pmr::vector<std::uint32_t>& used,
                 std::pmr::vector<std::uint32_t>& representative,
                 std::pmr::memory_resource* memory) {
    using Cell = std::array<std::int64_t, 3>;
    const Eigen::Vector3d origin = scan.bounds.min();
    const auto cell_of = [&](std::uint32_t vertex) {
        const Eigen::Vector3d p = (Eigen::Vector3d(mesh.positions[vertex]) - origin) / distance;
        return Cell{std::int64_t(p.x()), std::int64_t(p.y()), std::int64_t(p.z())};
    };
    // The occupied cells by number, and a table at most half full from a
    // cell to its number + 1 (0: empty).
    std::pmr::vector<Cell> cells(memory);
    std::size_t table_size = 1;
    while (table_size < 2 * used.size()) table_size *= 2;
    std::pmr::vector<std::uint32_t> table(table_size, 0, memory);
    const auto slot_of = [&](const Cell& cell) {
        const std::size_t mask = table.size() - 1;
        std::size_t slot = position_hash({std::uint64_t(cell[0]), std::uint64_t(cell[1]),
                                          std::uint64_t(cell[2])}) &
                           mask;
        while (table[slot] != 0 && cells[table[slot] - 1] != cell) slot = (slot + 1) & mask;
        return slot;
    };
    std::pmr::vector<std::uint32_t> cell_of_used(used.size(), memory);
    for (std::size_t u = 0; u < used.size(); ++u) {
        const Cell cell = cell_of(used[u]);
        const std::size_t slot = slot_of(cell);
        if (table[slot] == 0) {
            cells.push_back(cell);
            table[slot] = std::uint32_t(cells.size());
        }
        cell_of_used[u] = table[slot] - 1;
    }
    // Each cell's vertices, ascending, from members[starts[c]] to members[starts[c + 1]].
    std::pmr::vector<std::size_t> starts(cells.size() + 1, 0, memory);
    for (const std::uint32_t cell : cell_of_used) ++starts[cell + 1];
    for (std::size_t c = 0; c < cells.size(); ++c) starts[c + 1] += starts[c];
    std::pmr::vector<std::uint32_t> members(used.size(), memory);
    {
        std::pmr::vector<std::size_t> next(starts.begin(), starts.end() - 1, memory);
        for (std::size_t u = 0; u < used.size(); ++u) members[next[cell_of_used[u]]++] = used[u];
    }
    const auto close = [&](std::uint32_t a, std::uint32_t b) {
        const Eigen::Vector3d pa = mesh.positions[a];
        const Eigen::Vector3d pb = mesh.positions[b];
        return ((pa - pb).cwiseAbs().array() <= distance).all();
    };
    std::array<Cell, 13> offsets;
    std::size_t offset_count = 0;
    for (std::int64_t dx = 0; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
            for (std::int64_t dz = -1; dz <= 1; ++dz)
                if (dx > 0 || dy > 0 || (dy == 0 && dz > 0)) offsets[offset_count++] = {dx, dy, dz};

    SmallestIndexSets sets(representative);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const std::uint32_t* first = &members[starts[c]];
        const std::uint32_t* last = &members[0] + starts[c + 1];
        for (const std::uint32_t* vertex = first + 1; vertex != last; ++vertex)
            sets.join(*first, *vertex);
        for (const Cell& offset : offsets) {
            const std::size_t slot = slot_of(
                {cells[c][0] + offset[0], cells[c][1] + offset[1], cells[c][2] + offset[2]});
            if (table[slot] == 0) continue;
            const std::size_t n = table[slot] - 1;
            const std::uint32_t* near_first = &members[starts[n]];
            const std::uint32_t* near_last = &members[0] + starts[n + 1];
            auto touching = [&] {
                for (const std::uint32_t* a = first; a != last; ++a)
                    for (const std::uint32_t* b = near_first; b != near_last; ++b)
                        if (close(*a, *b)) return true;
                return false;
            };
            // Already one (through a chain): no pair need be compared.
            if (sets.find(*first) != sets.find(*near_first) && touching())
                sets.join(*first, *near_first);
        }
    }
    for (const std::uint32_t vertex : used) representative[vertex] = sets.find(vertex);
}

}  // namespace

template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_vertices(const MeshView<Scalar, Index>& mesh,
                                              const MeshScan& scan, double tolerance,
                                              std::pmr::memory_resource* memory) {
    std::pmr::vector<std::uint32_t> used(memory);
    std::pmr::vector<std::uint32_t> representative = identity_map(mesh, scan, used, memory);
    // At least 2^-50 of the extent (a few of its ulps), so that every cell
    // coordinate fits in an int64. Zero (an exact weld, or a mesh that is one
    // point) and an extent past the largest double weld exact copies only.
    const double extent = scan.bounds.isEmpty() ? 0.0 : scan.bounds.sizes().maxCoeff();
    const double distance = std::max(tolerance, 0x1p-50) * extent;
    if (tolerance > 0.0 && distance > 0.0 && std::isfinite(distance))
        weld_within(mesh, scan, distance, used, representative, memory);
    else
        weld_exact(mesh, used, representative, memory);
    return representative;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                                \
    template std::pmr::vector<std::uint32_t> weld_vertices<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const MeshScan&, double, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
