#include "topology.hpp"

#include <vector>

#include "radix_sort.hpp"

namespace polymass::core {
namespace {

// An undirected edge (low, high) as one number: low's bits above high's. Only
// as many bits as the vertex numbers need, so the keys sort in fewer passes.
struct EdgeKeys {
    int shift = 1;

    explicit EdgeKeys(std::size_t vertex_count) {
        while (shift < 32 && (std::uint64_t{1} << shift) < vertex_count) ++shift;
    }
    std::uint64_t key(std::uint32_t low, std::uint32_t high) const {
        return (std::uint64_t{low} << shift) | high;
    }
    std::uint32_t low(std::uint64_t key) const { return std::uint32_t(key >> shift); }
    std::uint32_t high(std::uint64_t key) const {
        return std::uint32_t(key & ((std::uint64_t{1} << shift) - 1));
    }
};

}  // namespace

template <class Scalar, class Index>
TopologyReport analyse_topology(const MeshView<Scalar, Index>& mesh,
                                const std::uint32_t* vertex_ids,
                                std::pmr::memory_resource* memory) {
    auto id = [&](std::size_t position) {
        const std::uint32_t vertex = mesh.indices[position];
        return vertex_ids ? vertex_ids[vertex] : vertex;
    };
    // Undirected keys (low, high), split by direction: "up" edges go from the
    // lower vertex to the higher, "down" edges the other way. A face has as
    // many edges as vertices, so index_count slots hold both lists: up from the
    // front, down from the back.
    const EdgeKeys edges(mesh.vertex_count);
    std::pmr::vector<std::uint64_t> keys(mesh.index_count, memory);
    std::size_t up_end = 0, down_begin = keys.size();
    for_each_face(mesh, [&](std::size_t, std::size_t first, std::size_t size) {
        for (std::size_t i = 0; i < size; ++i) {
            const std::uint32_t from = id(first + i);
            const std::uint32_t to = id(first + (i + 1) % size);
            if (from < to) keys[up_end++] = edges.key(from, to);
            if (from > to) keys[--down_begin] = edges.key(to, from);
        }
    });
    std::uint64_t* const up = keys.data();
    std::uint64_t* const up_last = up + up_end;
    std::uint64_t* const down = keys.data() + down_begin;
    std::uint64_t* const down_last = keys.data() + keys.size();
    radix_sort(up, up_last, memory);
    radix_sort(down, down_last, memory);

    TopologyReport report;
    const std::uint64_t* u = up;
    const std::uint64_t* d = down;
    while (u != up_last || d != down_last) {
        const std::uint64_t key = (d == down_last || (u != up_last && *u < *d)) ? *u : *d;
        std::size_t ups = 0, downs = 0;
        for (; u != up_last && *u == key; ++u) ++ups;
        for (; d != down_last && *d == key; ++d) ++downs;
        ++report.edge_count;
        const std::uint32_t low = edges.low(key), high = edges.high(key);
        // Name the edge in the direction it was (most often) traversed.
        const std::uint32_t from = ups >= downs ? low : high, to = ups >= downs ? high : low;
        if (ups + downs == 1) {
            report.open.record(from, to, 1);
        } else if (ups + downs == 2) {
            if (ups != 1) report.misoriented.record(from, to, 2);
        } else {
            report.non_manifold.record(from, to, ups + downs);
            if (ups != downs) report.non_manifold_balanced = false;
        }
    }
    return report;
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                  \
    template TopologyReport analyse_topology<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const std::uint32_t*, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
