#include "shells.hpp"

#include <numeric>
#include <string>
#include <vector>

#include "vertex_welder.hpp"

namespace polymass_cli {
namespace {

// Union-find over vertices with path halving.
class DisjointSets {
public:
    explicit DisjointSets(size_t count) : parent_(count) {
        std::iota(parent_.begin(), parent_.end(), 0u);
    }
    uint32_t root(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void join(uint32_t a, uint32_t b) { parent_[root(a)] = root(b); }

private:
    std::vector<uint32_t> parent_;
};

}  // namespace

std::vector<Part> split_shells(const Model& model, const Part& part) {
    // One index per distinct position, so an unwelded soup counts as its solid.
    std::vector<double> distinct;
    VertexWelder welder(distinct);
    std::vector<uint32_t> welded(model.vertex_count());
    for (uint64_t v = 0; v < model.vertex_count(); ++v) {
        welded[v] = welder.index_of(model.positions[3 * v], model.positions[3 * v + 1],
                                    model.positions[3 * v + 2]);
    }
    DisjointSets sets(distinct.size() / 3);
    std::vector<uint32_t> face_vertex;  // a welded vertex of each face, or kIndexOutOfRange
    uint64_t corner = 0;
    for (const uint32_t size : part.face_sizes) {
        uint32_t first = kIndexOutOfRange;
        for (uint32_t i = 0; i < size; ++i, ++corner) {
            const uint32_t index = part.indices[corner];
            if (index >= model.vertex_count()) continue;  // reported as a bad index
            const uint32_t vertex = welded[index];
            if (first == kIndexOutOfRange) {
                first = vertex;
            } else {
                sets.join(vertex, first);
            }
        }
        face_vertex.push_back(first);
    }
    std::vector<Part> shells;
    std::vector<uint32_t> shell_of_root(distinct.size() / 3, kIndexOutOfRange);
    corner = 0;
    for (size_t face = 0; face < part.face_sizes.size(); ++face) {
        const uint32_t size = part.face_sizes[face];
        if (face_vertex[face] != kIndexOutOfRange) {
            uint32_t& shell = shell_of_root[sets.root(face_vertex[face])];
            if (shell == kIndexOutOfRange) {
                shell = static_cast<uint32_t>(shells.size());
                shells.push_back(Part{"shell " + std::to_string(shells.size() + 1), {}, {}});
            }
            Part& target = shells[shell];
            target.indices.insert(target.indices.end(), part.indices.begin() + corner,
                                  part.indices.begin() + corner + size);
            target.face_sizes.push_back(size);
        }
        corner += size;
    }
    return shells;
}

}  // namespace polymass_cli
