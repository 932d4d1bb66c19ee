#include "topology.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace polymass::core {
namespace {

// Each directed edge is filed under its lower vertex as one Entry:
// (higher vertex << 1) | (1 when it runs from the higher vertex down to the
// lower). A counting sort by the lower vertex (one pass counting, one
// filing) replaces a sort of 64-bit keys: 4 bytes an edge instead of 16, and
// two passes instead of four. The buckets are short (a vertex is the lower
// end of about three edges), so sorting each one is cheap, and walking the
// buckets in order visits the edges in ascending (lower, higher) order, which
// keeps the findings' "lowest first".
//
// Entry is 32 bits when every vertex number fits in 31 bits and the entries
// fit 32-bit offsets; 64 bits otherwise (meshes of billions of indices).
template <class Entry, class Scalar, class Index, class VertexId>
TopologyReport match_edges(const MeshView<Scalar, Index>& mesh, VertexId&& id,
                           std::pmr::memory_resource* memory) {
    // end_of[v]: first counts, then (after the prefix sum) where v's bucket
    // starts, then (after filing, each bucket filled from its start) where it ends.
    std::pmr::vector<Entry> end_of(mesh.vertex_count, Entry{0}, memory);
    auto each_edge = [&](auto&& visit) {
        for_each_face(mesh, [&](std::size_t, std::size_t first, std::size_t size) {
            std::uint32_t from = id(first + size - 1);
            for (std::size_t i = 0; i < size; ++i) {
                const std::uint32_t to = id(first + i);
                if (from != to) visit(from, to);
                from = to;
            }
        });
    };
    each_edge([&](std::uint32_t from, std::uint32_t to) { ++end_of[std::min(from, to)]; });
    Entry edge_total = 0;
    for (Entry& count : end_of) edge_total += std::exchange(count, edge_total);
    std::pmr::vector<Entry> entries(edge_total, memory);
    each_edge([&](std::uint32_t from, std::uint32_t to) {
        const bool down = from > to;
        entries[end_of[down ? to : from]++] = (Entry(down ? from : to) << 1) | Entry(down);
    });

    TopologyReport report;
    Entry begin = 0;
    for (std::size_t low = 0; low < end_of.size(); ++low) {
        Entry* const first = entries.data() + begin;
        Entry* const last = entries.data() + end_of[low];
        begin = end_of[low];
        std::sort(first, last);  // by higher vertex, ups (bit 0) before downs
        for (Entry* at = first; at != last;) {
            const Entry high = *at >> 1;
            std::size_t ups = 0, downs = 0;
            for (; at != last && (*at >> 1) == high; ++at) (*at & 1 ? downs : ups) += 1;
            ++report.edge_count;
            // Name the edge in the direction it was (most often) traversed.
            const auto lower = std::uint32_t(low), higher = std::uint32_t(high);
            const std::uint32_t from = ups >= downs ? lower : higher;
            const std::uint32_t to = ups >= downs ? higher : lower;
            if (ups + downs == 1) {
                report.open.record(from, to, 1);
            } else if (ups + downs == 2) {
                if (ups != 1) report.misoriented.record(from, to, 2);
            } else {
                report.non_manifold.record(from, to, ups + downs);
                if (ups != downs) report.non_manifold_balanced = false;
            }
        }
    }
    return report;
}

}  // namespace

template <class Scalar, class Index>
TopologyReport analyse_topology(const MeshView<Scalar, Index>& mesh,
                                const std::uint32_t* vertex_ids,
                                std::pmr::memory_resource* memory) {
    auto analyse = [&](auto&& id) {
        const bool narrow = mesh.vertex_count <= (std::size_t{1} << 31) &&
                            mesh.index_count <= std::numeric_limits<std::uint32_t>::max();
        return narrow ? match_edges<std::uint32_t>(mesh, id, memory)
                      : match_edges<std::uint64_t>(mesh, id, memory);
    };
    if (vertex_ids)
        return analyse([&](std::size_t position) { return vertex_ids[mesh.indices[position]]; });
    return analyse([&](std::size_t position) { return mesh.indices[position]; });
}

#define POLYMASS_INSTANTIATE(Scalar, Index)                  \
    template TopologyReport analyse_topology<Scalar, Index>( \
        const MeshView<Scalar, Index>&, const std::uint32_t*, std::pmr::memory_resource*);
POLYMASS_FOR_EACH_MESH_VIEW(POLYMASS_INSTANTIATE)
#undef POLYMASS_INSTANTIATE

}  // namespace polymass::core
