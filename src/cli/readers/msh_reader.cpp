// MuJoCo's binary mesh (.msh; MuJoCo XML reference, mesh/file): four
// little-endian int32 counts nvertex, nnormal, ntexcoord, nface, then
// float32 vertex positions [3 * nvertex], normals [3 * nnormal], texture
// coordinates [2 * ntexcoord], and int32 triangle corners [3 * nface]. MuJoCo
// requires the file to be exactly that long, and so does this reader: every
// count is checked against the file's length before anything is allocated, so
// a hostile header is a clear error, never a large allocation. Normals and
// texture coordinates are skipped (the corners' order says which side is
// out). The positions are floats in the file, kept so (model.hpp's Positions).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "readers/format_readers.hpp"
#include "readers/little_endian.hpp"
#include "readers/mesh_reader.hpp"

namespace polymass_cli {
namespace {

constexpr uint64_t kHeaderBytes = 16;

const unsigned char* at(std::string_view bytes, uint64_t offset) {
    return reinterpret_cast<const unsigned char*>(bytes.data()) + offset;
}

}  // namespace

Model read_msh(std::string_view bytes) {
    if (bytes.compare(0, 11, "$MeshFormat") == 0) {
        throw ReadError(
            "a Gmsh mesh, not MuJoCo's binary .msh: convert it to STL or OBJ (e.g. gmsh -o)");
    }
    if (bytes.size() < kHeaderBytes) {
        throw ReadError(
            "not a MuJoCo .msh: it starts with four int32 counts (16 bytes), but the "
            "file has " +
            std::to_string(bytes.size()) + " bytes");
    }
    const char* names[] = {"nvertex", "nnormal", "ntexcoord", "nface"};
    int64_t counts[4];
    std::string header;
    for (int k = 0; k < 4; ++k) {
        counts[k] = little_endian_i32(at(bytes, 4 * k));
        header += std::string(k ? ", " : "") + names[k] + " " + std::to_string(counts[k]);
        if (counts[k] < 0) throw ReadError("not a MuJoCo .msh: negative count (" + header + ")");
    }
    const uint64_t vertex_count = uint64_t(counts[0]), face_count = uint64_t(counts[3]);
    // Each count is below 2^31: the sum cannot overflow.
    const uint64_t expected = kHeaderBytes + 12 * vertex_count + 12 * uint64_t(counts[1]) +
                              8 * uint64_t(counts[2]) + 12 * face_count;
    if (expected != bytes.size()) {
        throw ReadError("not a MuJoCo .msh, or truncated: its counts (" + header + ") make " +
                        std::to_string(expected) + " bytes, but the file has " +
                        std::to_string(bytes.size()));
    }
    if (face_count == 0) {
        throw ReadError("the .msh has " + std::to_string(vertex_count) +
                        " vertices and no faces (MuJoCo would take their convex hull): "
                        "no surface to integrate");
    }
    Model model;
    std::vector<float> positions(3 * vertex_count);
    for (uint64_t k = 0; k < 3 * vertex_count; ++k)
        positions[k] = little_endian_f32(at(bytes, kHeaderBytes + 4 * k));
    model.positions = Positions(std::move(positions));
    const uint64_t faces_at = expected - 12 * face_count;
    Part& part = model.parts.emplace_back();
    part.indices.reserve(3 * face_count);
    for (uint64_t k = 0; k < 3 * face_count; ++k) {
        const int32_t index = little_endian_i32(at(bytes, faces_at + 4 * k));
        part.indices.push_back(index < 0 ? kIndexOutOfRange : uint32_t(index));
    }
    return model;
}

}  // namespace polymass_cli
