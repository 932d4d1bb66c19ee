#include "library/parts_apart.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

namespace polymass_cli {
namespace {

constexpr uint32_t kUnset = std::numeric_limits<uint32_t>::max();

// Each corner of part given its welded vertex, numbered as the file does:
// the part's used vertices are copied out (so that the library's weld, which
// writes one entry per position, costs the part's size and not the file's),
// welded at the library's tolerance, and mapped back. local_of is kUnset for
// every vertex on entry and on return. False when the library cannot weld
// the part.
bool welded_corners(const Library& library, const Model& model, const Part& part,
                    std::vector<uint32_t>& local_of, std::vector<uint32_t>& corners) {
    std::vector<uint32_t> file_of;  // the file's number of each local vertex
    std::vector<double> positions;
    std::vector<uint32_t> local_indices;
    local_indices.reserve(part.indices.size());
    bool in_range = true;
    for (const uint32_t index : part.indices) {
        if (index >= model.vertex_count()) {
            in_range = false;
            break;
        }
        if (local_of[index] == kUnset) {
            local_of[index] = uint32_t(file_of.size());
            file_of.push_back(index);
            const std::array<double, 3> p = model.positions.vertex(index);
            positions.insert(positions.end(), p.begin(), p.end());
        }
        local_indices.push_back(local_of[index]);
    }
    for (const uint32_t index : file_of) local_of[index] = kUnset;
    if (!in_range) return false;

    std::vector<uint32_t> welded(file_of.size());
    uint64_t distinct = 0;
    const int32_t status = polymass_weld_positions(
        welded.data(), &distinct, library.context(), positions.data(), POLYMASS_POSITION_FLOAT64,
        file_of.size(), 0, library.options().weld_tolerance);
    if (status == POLYMASS_ERROR_OUT_OF_MEMORY) throw std::bad_alloc();
    if (status != POLYMASS_OK) return false;
    corners.clear();
    for (const uint32_t local : local_indices) corners.push_back(file_of[welded[local]]);
    return true;
}

}  // namespace

std::optional<PartsApart> parts_apart(const Library& library, const Model& model) {
    PartsApart apart;
    apart.model.format = model.format;
    // Doubles, the file's first and then the copies (widened when the
    // file's are float32: the same values).
    apart.model.positions = model.positions;
    std::vector<double>& wide = apart.model.positions.as_doubles();
    Part& all = apart.model.parts.emplace_back();
    all.name = "combined";
    const size_t file_count = model.vertex_count();
    std::vector<uint32_t> scratch(file_count, kUnset);
    // The part that first used each file vertex; a later part gets a copy,
    // once (copy_of, reset after each part).
    std::vector<uint32_t> owner(file_count, kUnset);
    std::vector<uint32_t> copy_of(file_count, kUnset);
    std::vector<uint32_t> corners;
    for (size_t k = 0; k < model.parts.size(); ++k) {
        const Part& part = model.parts[k];
        if (!welded_corners(library, model, part, scratch, corners)) return std::nullopt;
        std::vector<uint32_t> copied;
        for (const uint32_t v : corners) {
            if (owner[v] == kUnset) owner[v] = uint32_t(k);
            if (owner[v] == k) {
                all.indices.push_back(v);
                continue;
            }
            if (copy_of[v] == kUnset) {
                const uint64_t copy = apart.model.vertex_count();
                if (copy >= kUnset) throw std::length_error("more than 2^32 - 1 vertices");
                copy_of[v] = uint32_t(copy);
                copied.push_back(v);
                const std::array<double, 3> p = model.positions.vertex(v);
                wide.insert(wide.end(), p.begin(), p.end());
            }
            all.indices.push_back(copy_of[v]);
        }
        for (const uint32_t v : copied) copy_of[v] = kUnset;
        for (uint64_t face = 0; face < part.face_count(); ++face)
            all.face_sizes.push_back(part.face_size(face));
    }
    all.drop_triangle_sizes();
    return apart;
}

polymass_options unwelded_options(const polymass_options& options) {
    polymass_options unwelded = options;
    unwelded.flags &= ~uint32_t(POLYMASS_OPTION_WELD_VERTICES);
    return unwelded;
}

}  // namespace polymass_cli
