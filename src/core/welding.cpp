#include "welding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory_resource>
#include <numeric>
#include <utility>

#include "position_hash.hpp"
#include "radix_sort.hpp"
#include "scratch_buffer.hpp"
#include "smallest_index_sets.hpp"

namespace polymass::core {
namespace {

// How many vertices a weld maps: every one up to the last a face may use,
// those the scan's words of used bits cover (known before the scan, for the
// weld that follows it).
template <class Scalar, class Index>
std::size_t welded_count(const MeshView<Scalar, Index>& mesh) {
    return std::min(mesh.vertex_count, (addressable_vertices(mesh) + 63) / 64 * 64);
}

// The used vertices among the first `count`, in index order.
std::pmr::vector<std::uint32_t> used_vertices(const MeshScan& scan, std::size_t count,
                                              std::pmr::memory_resource* memory) {
    std::pmr::vector<std::uint32_t> used(memory);
    used.reserve(scan.used_vertex_count);
    for (std::size_t vertex = 0; vertex < count; ++vertex)
        if (scan.is_used(vertex)) used.push_back(std::uint32_t(vertex));
    return used;
}

// A position's bits as the exact weld compares them: each coordinate's
// position_bits in the mesh's own precision (a float32 one in half a
// double's room), read without the positions' accessor, which widens to
// double (and the comparison narrowed float32 back again).
template <class Scalar>
using PositionBits = std::array<decltype(position_bits(Scalar())), 3>;

template <class Scalar>
PositionBits<Scalar> bits_at(const PositionArray<Scalar>& positions, std::uint32_t vertex) {
    PositionBits<Scalar> bits;
    const unsigned char* xyz = positions.base + std::size_t(vertex) * positions.stride;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        Scalar value;
        std::memcpy(&value, xyz + axis * sizeof(Scalar), sizeof value);
        bits[axis] = position_bits(value);
    }
    return bits;
}

// The hash of a vertex's position, for the exact weld: of its bits as the
// weld compares them.
template <class Scalar, class Index>
std::uint64_t hash_of_vertex(const MeshView<Scalar, Index>& mesh, std::uint32_t vertex) {
    const PositionBits<Scalar> bits = bits_at(mesh.positions, vertex);
    return position_hash({bits[0], bits[1], bits[2]});
}

// One hashing pass over the used vertices in index order (no list of them): the
// first vertex met at a position (the lowest index) enters the table, and the
// position is numbered in the order met; every later vertex with the same bits
// gets that number. lowest() is each number's lowest vertex, ascending. In
// shares (weld_exact), the pass runs over each share of the positions, chosen
// by hash, with a table of its own: every copy of a position is in one share,
// so each vertex meets in its share the same lowest vertex as in one pass over
// all (the numbers, the share's own, are then merged). The pass takes its
// items in ascending runs (take), each as soon as the scan has bounded them
// when it follows the scan (scan_and_weld_exact); the answer is the same
// however the items are cut into runs. The table holds only
// distinct positions (a triangle soup asks about each corner, but has a sixth
// as many vertices), in open addressing with linear probing, at most half
// full, and beside it a copy of each distinct position, so that a probe
// compares with the copy rather than with the held vertex in the soup, where
// it may be far back. Each slot keeps the position's number with the high half
// of its hash, so that a probe reads a held position's bits only when the
// halves agree (almost only for a copy), and the slot of a vertex a few ahead
// in the run is prefetched. A vertex's first slot is taken from that high half
// too, so that the table grows by moving its slots alone. Comparing bits rather
// than values is exact welding for finite coordinates and still defined for NaN
// (copies of one NaN are one vertex), which sorting is not.
template <class Scalar, class Index, class VertexAt, class HashOf>
class HashingPass {
public:
    HashingPass(const MeshView<Scalar, Index>& mesh, VertexAt vertex_at, HashOf hash_of,
                std::uint32_t* number_of, std::pmr::memory_resource* memory)
        : mesh_(mesh),
          vertex_at_(std::move(vertex_at)),
          hash_of_(std::move(hash_of)),
          number_of_(number_of),
          slots_(std::size_t(1) << 12, 0, memory),
          lowest_(memory),
          held_(memory) {}

    // Items [first, last); `scan` holds the used bits of their vertices.
    void take(const MeshScan& scan, std::size_t first, std::size_t last) {
        // The hashes of the next kAhead items of the run, by item % kAhead
        // (stale for an unused vertex, which is never looked up).
        std::array<std::uint64_t, kAhead> ahead{};
        const auto hash_ahead = [&](std::size_t item) {
            if (item >= last || !scan.is_used(vertex_at_(item))) return;
            const std::uint64_t hash = hash_of_(vertex_at_(item));
            ahead[item % kAhead] = hash;
            __builtin_prefetch(&slots_[home(hash)]);
        };
        for (std::size_t item = first; item < first + kAhead; ++item) hash_ahead(item);
        for (std::size_t item = first; item < last; ++item) {
            const std::uint64_t hash = ahead[item % kAhead];  // before its slot is reused
            hash_ahead(item + kAhead);
            const std::uint32_t vertex = vertex_at_(item);
            if (scan.is_used(vertex)) number(vertex, hash);
        }
    }

    std::pmr::vector<std::uint32_t> lowest() && { return std::move(lowest_); }

private:
    static constexpr std::size_t kAhead = 16;
    using Bits = PositionBits<Scalar>;
    static constexpr std::uint64_t kHighHalf = 0xFFFFFFFF00000000ull;
    // The first slot to probe for a hash, or for a slot holding it.
    std::size_t home(std::uint64_t hash_or_slot) const {
        return std::size_t(hash_or_slot >> 32) & (slots_.size() - 1);
    }
    void place(std::uint64_t entry) {
        const std::size_t mask = slots_.size() - 1;
        std::size_t slot = home(entry);
        while (slots_[slot] != 0) slot = (slot + 1) & mask;
        slots_[slot] = entry;
    }

    void number(std::uint32_t vertex, std::uint64_t hash) {
        const Bits bits = bits_at(mesh_.positions, vertex);
        const std::uint64_t tag = hash & kHighHalf;
        const std::size_t mask = slots_.size() - 1;
        std::size_t slot = home(hash);
        for (; slots_[slot] != 0; slot = (slot + 1) & mask) {
            const std::uint64_t entry = slots_[slot];
            if ((entry & kHighHalf) != tag) continue;
            const Bits& copy = held_[std::uint32_t(entry) - 1];
            if (copy[0] == bits[0] && copy[1] == bits[1] && copy[2] == bits[2]) break;
        }
        if (slots_[slot] != 0) {
            number_of_[vertex] = std::uint32_t(slots_[slot]) - 1;
            return;
        }
        number_of_[vertex] = std::uint32_t(lowest_.size());
        // A slot: the hash's high half, then the position's number + 1 (0: empty).
        slots_[slot] = tag | (std::uint64_t(lowest_.size()) + 1);
        lowest_.push_back(vertex);
        held_.push_back(bits);
        if (2 * lowest_.size() > slots_.size()) {
            std::pmr::vector<std::uint64_t> moved(std::move(slots_));
            slots_ = std::pmr::vector<std::uint64_t>(2 * moved.size(), 0, moved.get_allocator());
            for (const std::uint64_t entry : moved)
                if (entry != 0) place(entry);
        }
    }

    const MeshView<Scalar, Index>& mesh_;
    VertexAt vertex_at_;
    HashOf hash_of_;
    std::uint32_t* number_of_;
    std::pmr::vector<std::uint64_t> slots_;
    std::pmr::vector<std::uint32_t> lowest_;  // of each number
    std::pmr::vector<Bits> held_;             // of each number, its position's bits
};

template <class Scalar, class Index, class VertexAt, class HashOf>
HashingPass<Scalar, Index, VertexAt, HashOf> hashing_pass(const MeshView<Scalar, Index>& mesh,
                                                          VertexAt vertex_at, HashOf hash_of,
                                                          std::uint32_t* number_of,
                                                          std::pmr::memory_resource* memory) {
    return {mesh, std::move(vertex_at), std::move(hash_of), number_of, memory};
}

// The one pass of the exact weld over every vertex, in index order.
template <class Scalar, class Index>
auto whole_hashing_pass(const MeshView<Scalar, Index>& mesh, std::uint32_t* number_of,
                        std::pmr::memory_resource* memory) {
    return hashing_pass(
        mesh, [](std::size_t item) { return std::uint32_t(item); },
        [&mesh](std::uint32_t vertex) { return hash_of_vertex(mesh, vertex); }, number_of, memory);
}

// The exact weld, numbered, in shares on `tasks` (a share a thread, each of at
// least a block of used vertices; the answer is the same for any number of
// shares). Every used vertex is hashed once, in blocks of kItemsPerBlock, and
// dealt to its share, in index order (the order a share's pass reads them in:
// with a few shares, almost every position in turn). Each share allocates its
// own table and list of lowest vertices, taken from `memory` one thread at a
// time. The shares' numbers are then merged into one numbering in the order of
// the lowest vertices: each share's are marked in a bit set over the vertices,
// whose walk in index order takes them lowest first, whatever the number of
// shares (rather than comparing every share's next one for each position).
// Then every vertex is renumbered, in blocks.
template <class Scalar, class Index>
NumberedVertices weld_exact(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                            TaskRunner& tasks, std::pmr::memory_resource* memory) {
    NumberedVertices numbered(memory);
    const std::size_t count = welded_count(mesh);
    numbered.of_vertex.resize(count);
    std::uint32_t* const number_of = numbered.of_vertex.data();
    const std::size_t shares = std::max<std::size_t>(
        1, std::min(tasks.concurrency(), scan.used_vertex_count / kItemsPerBlock));
    if (shares == 1) {
        auto pass = whole_hashing_pass(mesh, number_of, memory);
        pass.take(scan, 0, count);
        numbered.lowest_vertex = std::move(pass).lowest();
        return numbered;
    }
    // A share from the hash's high half's highest bits (its lowest pick the slot).
    const auto share_of = [shares](std::uint32_t high_half) {
        return std::size_t((std::uint64_t(high_half) * shares) >> 32);
    };
    const std::size_t blocks = block_count(count, kItemsPerBlock);
    const auto each_used = [&](auto&& visit) {
        for_each_in_numbered_blocks(count, kItemsPerBlock, tasks,
                                    [&](std::size_t block, std::size_t vertex) {
                                        if (scan.is_used(vertex))
                                            visit(block, std::uint32_t(vertex));
                                    });
    };
    ScratchBuffer<std::uint32_t> high_halves(count, memory);
    // ends[block * shares + share]: the block's count, then where its next vertex goes.
    std::pmr::vector<std::size_t> ends(blocks * shares, 0, memory);
    each_used([&](std::size_t block, std::uint32_t vertex) {
        high_halves[vertex] = std::uint32_t(hash_of_vertex(mesh, vertex) >> 32);
        ++ends[block * shares + share_of(high_halves[vertex])];
    });
    std::pmr::vector<std::size_t> share_starts(shares + 1, memory);
    std::size_t dealt = 0;
    for (std::size_t share = 0; share < shares; ++share) {
        share_starts[share] = dealt;
        for (std::size_t block = 0; block < blocks; ++block)
            dealt += std::exchange(ends[block * shares + share], dealt);
    }
    share_starts[shares] = dealt;
    ScratchBuffer<std::uint32_t> in_shares(dealt, memory);
    each_used([&](std::size_t block, std::uint32_t vertex) {
        in_shares[ends[block * shares + share_of(high_halves[vertex])]++] = vertex;
    });
    std::pmr::synchronized_pool_resource one_at_a_time(memory);
    std::pmr::vector<std::pmr::vector<std::uint32_t>> lowest_of_share(shares, &one_at_a_time);
    tasks.run(shares, [&](std::size_t share) {
        const std::uint32_t* const own = in_shares.data() + share_starts[share];
        auto pass = hashing_pass(
            mesh, [own](std::size_t item) { return own[item]; },
            [&](std::uint32_t vertex) { return std::uint64_t(high_halves[vertex]) << 32; },
            number_of, &one_at_a_time);
        pass.take(scan, 0, share_starts[share + 1] - share_starts[share]);
        lowest_of_share[share] = std::move(pass).lowest();
    });
    // first_of_share[share]: where the share's numbers start in `renumbered`,
    // which gives each the number it has among all shares'.
    std::pmr::vector<std::size_t> first_of_share(shares + 1, 0, memory);
    std::pmr::vector<std::uint64_t> is_lowest((count + 63) / 64, 0, memory);
    for (std::size_t share = 0; share < shares; ++share) {
        first_of_share[share + 1] = first_of_share[share] + lowest_of_share[share].size();
        for (const std::uint32_t vertex : lowest_of_share[share])
            is_lowest[vertex / 64] |= std::uint64_t{1} << (vertex % 64);
    }
    const std::size_t distinct = first_of_share[shares];
    std::pmr::vector<std::uint32_t> renumbered(distinct, memory);
    numbered.lowest_vertex.resize(distinct);
    std::uint32_t number = 0;
    for (std::size_t word = 0; word < is_lowest.size(); ++word)
        for (std::uint64_t bits = is_lowest[word]; bits != 0; bits &= bits - 1) {
            const auto vertex = std::uint32_t(64 * word + std::size_t(__builtin_ctzll(bits)));
            // A lowest vertex's number in its share is its position's.
            renumbered[first_of_share[share_of(high_halves[vertex])] + number_of[vertex]] = number;
            numbered.lowest_vertex[number++] = vertex;
        }
    each_used([&](std::size_t, std::uint32_t vertex) {
        number_of[vertex] =
            renumbered[first_of_share[share_of(high_halves[vertex])] + number_of[vertex]];
    });
    return numbered;
}

// The exact weld's one pass as a follower of the scan.
template <class Pass>
class FollowingWeld final : public ScanFollower {
public:
    explicit FollowingWeld(Pass& pass) : pass_(pass) {}
    void follow(const MeshScan& scan, std::size_t first, std::size_t last) override {
        pass_.take(scan, first, last);
    }

private:
    Pass& pass_;
};

// What an exact weld can be asked of: indices in range (the weld reads the
// positions the faces use) and, for the analysis, finite coordinates.
bool weldable(const MeshScan& scan) {
    return scan.out_of_range_indices == 0 && scan.non_finite.count == 0;
}

// A grid of cells `distance` wide: vertices in one cell are within `distance`
// of each other in every coordinate (up to rounding), so they are one; vertices
// in adjacent cells are one when any pair across them is that close. Sorting
// the vertices by cell groups each cell's and lets a merge-like walk meet each
// cell's 26 neighbours. The cost is linear, but for the comparison sort of
// vertices sharing a slab of x (n log n when they all do), and unless many
// distinct vertices crowd two adjacent cells without touching (then it is
// their product).
// Returns each used vertex's lowest welded vertex, unused vertices their own.
template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_within(const MeshView<Scalar, Index>& mesh,
                                            const MeshScan& scan, double distance,
                                            std::pmr::memory_resource* memory) {
    std::pmr::vector<std::uint32_t> representative(welded_count(mesh), memory);
    std::iota(representative.begin(), representative.end(), 0u);
    const std::pmr::vector<std::uint32_t> used = used_vertices(scan, representative.size(), memory);
    using Cell = std::array<std::int64_t, 3>;
    // Cells compared coordinate by coordinate in line: std::array's own
    // operators call memcmp and a generic lexicographic loop, which were half
    // the weld of a million-triangle STL.
    const auto same_cell = [](const Cell& a, const Cell& b) {
        return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    };
    const auto cell_before = [](const Cell& a, const Cell& b) {
        if (a[0] != b[0]) return a[0] < b[0];
        if (a[1] != b[1]) return a[1] < b[1];
        return a[2] < b[2];
    };
    struct Entry {
        Cell cell;
        std::uint32_t vertex;
    };
    const Eigen::Vector3d origin = scan.bounds.min();
    const auto cell_of = [&](std::uint32_t vertex) {
        const Eigen::Vector3d p = (Eigen::Vector3d(mesh.positions[vertex]) - origin) / distance;
        return Cell{std::int64_t(p.x()), std::int64_t(p.y()), std::int64_t(p.z())};
    };
    const auto entry_before = [&](const Entry& a, const Entry& b) {
        return cell_before(a.cell, b.cell) || (same_cell(a.cell, b.cell) && a.vertex < b.vertex);
    };
    // The entries in that order: first by their cells' x alone, in linear
    // time (its high 32 bits, of at most 51, in a key above each entry's
    // place in `used`), then each run of one such key by a comparison sort,
    // which almost every run (a vertex alone in its slab of x) skips. A
    // comparison sort of all the entries was half of this weld.
    // (Each cell is computed again when the entries are laid out in that
    // order: keeping the first ones would need a second array of entries.)
    std::pmr::vector<std::uint64_t> keys(used.size(), memory);
    std::uint64_t last_x = 0;
    for (std::size_t i = 0; i < used.size(); ++i) {
        keys[i] = std::uint64_t(cell_of(used[i])[0]);
        last_x = std::max(last_x, keys[i]);
    }
    int x_shift = 0;
    while ((last_x >> x_shift) > UINT32_MAX) ++x_shift;
    for (std::size_t i = 0; i < used.size(); ++i) keys[i] = (keys[i] >> x_shift) << 32 | i;
    radix_sort_high_half(keys.data(), keys.data() + keys.size(), memory);
    std::pmr::vector<Entry> entries(memory);
    entries.reserve(used.size());
    for (const std::uint64_t key : keys) {
        const std::uint32_t vertex = used[std::uint32_t(key)];
        entries.push_back({cell_of(vertex), vertex});
    }
    for (std::size_t run = 0; run < keys.size();) {
        std::size_t end = run + 1;
        while (end < keys.size() && keys[end] >> 32 == keys[run] >> 32) ++end;
        if (end - run > 1) std::sort(entries.begin() + run, entries.begin() + end, entry_before);
        run = end;
    }
    let_go(keys);

    // Each occupied cell's first entry; the next cell's first ends it.
    std::pmr::vector<std::size_t> cell_starts(memory);
    for (std::size_t i = 0; i < entries.size(); ++i)
        if (i == 0 || !same_cell(entries[i].cell, entries[i - 1].cell)) cell_starts.push_back(i);
    const std::size_t cell_count = cell_starts.size();
    cell_starts.push_back(entries.size());
    const auto close = [&](const Entry& a, const Entry& b) {
        const Eigen::Vector3d pa = mesh.positions[a.vertex];
        const Eigen::Vector3d pb = mesh.positions[b.vertex];
        return ((pa - pb).cwiseAbs().array() <= distance).all();
    };
    // The 13 neighbours after a cell in sort order (the other 13 meet it from
    // their side): the first 4 in its own slab of x, the other 9 in the next.
    // Cells are visited in sort order, and so, shifted by one offset, are
    // their neighbours: one cursor per offset only moves forward.
    constexpr std::size_t same_slab_offsets = 4;
    std::array<Cell, 13> offsets;
    std::size_t offset_count = 0;
    for (std::int64_t dx = 0; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
            for (std::int64_t dz = -1; dz <= 1; ++dz)
                if (dx > 0 || dy > 0 || (dy == 0 && dz > 0)) offsets[offset_count++] = {dx, dy, dz};
    std::array<std::size_t, 13> cursors{};
    const auto cell_at = [&](std::size_t c) -> const Cell& { return entries[cell_starts[c]].cell; };

    SmallestIndexSets sets(representative);
    std::size_t slab_end = 0;  // the first cell past the slab of x of cell c
    for (std::size_t c = 0; c < cell_count; ++c) {
        const Entry* first = &entries[cell_starts[c]];
        const Entry* last = &entries[0] + cell_starts[c + 1];
        for (const Entry* entry = first + 1; entry != last; ++entry)
            sets.join(first->vertex, entry->vertex);
        // A slab holding no other cell after this one has none of the first 4
        // neighbours, and a next slab that is not x + 1 none of the other 9.
        // Cells a tolerance wide are far finer than a surface's vertices, so
        // most cells are alone in their slab with no slab beside it: looking
        // for their 13 neighbours in vain was half of this weld. (A cursor
        // left behind moves on when next asked: each still moves forward only.)
        if (slab_end == c) {
            while (slab_end < cell_count && cell_at(slab_end)[0] == first->cell[0]) ++slab_end;
        }
        const bool next_slab_beside =
            slab_end < cell_count && cell_at(slab_end)[0] == first->cell[0] + 1;
        const std::size_t from = c + 1 < slab_end ? 0 : same_slab_offsets;
        const std::size_t to = next_slab_beside ? offsets.size() : same_slab_offsets;
        for (std::size_t o = from; o < to; ++o) {
            const Cell near{first->cell[0] + offsets[o][0], first->cell[1] + offsets[o][1],
                            first->cell[2] + offsets[o][2]};
            std::size_t& n = cursors[o];
            while (n < cell_count && cell_before(cell_at(n), near)) ++n;
            if (n == cell_count || !same_cell(cell_at(n), near)) continue;
            const Entry* near_first = &entries[cell_starts[n]];
            const Entry* near_last = &entries[0] + cell_starts[n + 1];
            auto touching = [&] {
                for (const Entry* a = first; a != last; ++a)
                    for (const Entry* b = near_first; b != near_last; ++b)
                        if (close(*a, *b)) return true;
                return false;
            };
            // Already one (through a chain): no pair need be compared.
            if (sets.find(first->vertex) != sets.find(near_first->vertex) && touching())
                sets.join(first->vertex, near_first->vertex);
        }
    }
    for (const std::uint32_t vertex : used) representative[vertex] = sets.find(vertex);
    return representative;
}

// How close two vertices must be to be one: at least 2^-50 of the extent (a
// few of its ulps), so that every cell coordinate fits in an int64; 0 for an
// exact weld, and for a mesh that is one point or whose extent is past the
// largest double (they weld exact copies only).
double weld_distance(const MeshScan& scan, double tolerance) {
    const double extent = scan.bounds.isEmpty() ? 0.0 : scan.bounds.sizes().maxCoeff();
    const double distance = std::max(tolerance, 0x1p-50) * extent;
    return tolerance > 0.0 && std::isfinite(distance) ? distance : 0.0;
}

}  // namespace

template <class Scalar, class Index>
std::pmr::vector<std::uint32_t> weld_vertices(const MeshView<Scalar, Index>& mesh,
                                              const MeshScan& scan, double tolerance,
                                              TaskRunner& tasks,
                                              std::pmr::memory_resource* memory) {
    const double distance = weld_distance(scan, tolerance);
    if (distance > 0.0) return weld_within(mesh, scan, distance, memory);
    return lowest_welded_vertices(weld_exact(mesh, scan, tasks, memory), scan, memory);
}

template <class Scalar, class Index>
NumberedVertices weld_and_number(const MeshView<Scalar, Index>& mesh, const MeshScan& scan,
                                 double tolerance, TaskRunner& tasks,
                                 std::pmr::memory_resource* memory) {
    const double distance = weld_distance(scan, tolerance);
    if (distance == 0.0) return weld_exact(mesh, scan, tasks, memory);
    const std::pmr::vector<std::uint32_t> lowest = weld_within(mesh, scan, distance, memory);
    const std::size_t distinct = count_used_with(
        scan, lowest.size(), [&](std::uint32_t vertex) { return lowest[vertex] == vertex; });
    return number_welded_vertices(lowest, scan, distinct, memory);
}

template <class Scalar, class Index>
MeshScan scan_and_weld_exact(const MeshView<Scalar, Index>& mesh, NumberedVertices& numbered,
                             TaskRunner& tasks, std::pmr::memory_resource* memory) {
    numbered = NumberedVertices(memory);
    if (tasks.concurrency() > 1) {
        MeshScan scan = scan_mesh(mesh, memory, tasks);
        if (weldable(scan)) numbered = weld_exact(mesh, scan, tasks, memory);
        return scan;
    }
    numbered.of_vertex.resize(welded_count(mesh));
    auto pass = whole_hashing_pass(mesh, numbered.of_vertex.data(), memory);
    FollowingWeld<decltype(pass)> follower(pass);
    MeshScan scan = scan_mesh(mesh, memory, tasks, widest_instruction_set(), &follower);
    if (weldable(scan))
        numbered.lowest_vertex = std::move(pass).lowest();
    else
        numbered = NumberedVertices(memory);
    return scan;
}

std::pmr::vector<std::uint32_t> lowest_welded_vertices(const NumberedVertices& numbered,
                                                       const MeshScan& scan,
                                                       std::pmr::memory_resource* memory) {
    std::pmr::vector<std::uint32_t> lowest(numbered.of_vertex.size(), memory);
    for (std::size_t vertex = 0; vertex < lowest.size(); ++vertex)
        lowest[vertex] = scan.is_used(vertex) ? numbered.lowest_vertex[numbered.of_vertex[vertex]]
                                              : std::uint32_t(vertex);
    return lowest;
}

template <class Scalar>
WeldedPositions weld_positions(const PositionArray<Scalar>& positions, std::size_t count,
                               double tolerance, TaskRunner& tasks,
                               std::pmr::memory_resource* memory) {
    // A scan of the positions as if every one were used by a face.
    MeshScan scan(memory);
    scan.used.assign((count + 63) / 64, ~std::uint64_t{0});
    scan.used_vertex_count = count;
    WeldedPositions result(memory);
    // The extent and the non-finite positions matter to a weld within a
    // tolerance only: an exact weld compares bits, and skips this pass (an
    // eighth of a triangle soup's weld), leaving result.non_finite empty.
    if (tolerance > 0.0) {
        for (std::size_t vertex = 0; vertex < count; ++vertex) {
            const Eigen::Vector3d p = positions[vertex];
            if (p.allFinite())
                scan.bounds.extend(p);
            else
                result.non_finite.record(vertex);
        }
        scan.non_finite = result.non_finite;
        if (result.non_finite.count > 0) return result;
    }
    const MeshView<Scalar, std::uint32_t> mesh{positions, count, {}, 0, nullptr, 0};
    result.vertex_of = weld_vertices(mesh, scan, tolerance, tasks, memory);
    for (std::size_t vertex = 0; vertex < count; ++vertex)
        result.distinct += result.vertex_of[vertex] == vertex;
    return result;
}

template WeldedPositions weld_positions<double>(const PositionArray<double>&, std::size_t, double,
                                                TaskRunner&, std::pmr::memory_resource*);
template WeldedPositions weld_positions<float>(const PositionArray<float>&, std::size_t, double,
                                               TaskRunner&, std::pmr::memory_resource*);

#define POLYMASS_INSTANTIATE(Scalar, Index)                                                        \
    template std::pmr::vector<std::uint32_t> weld_vertices<Scalar, Index>(                         \
        const MeshView<Scalar, Index>&, const MeshScan&, double, TaskRunner&,                      \
        std::pmr::memory_resource*);                                                               \
    template NumberedVertices weld_and_number<Scalar, Index>(const MeshView<Scalar, Index>&,       \
                                                             const MeshScan&, double, TaskRunner&, \
                                                             std::pmr::memory_resource*);          \
    template MeshScan scan_and_weld_exact<Scalar, Index>(const MeshView<Scalar, Index>&,           \
                                                         NumberedVertices&, TaskRunner&,           \
                                                         std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
