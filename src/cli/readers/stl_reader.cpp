// STL, binary and ASCII. Binary: an 80-byte header, a little-endian uint32
// triangle count, then 50 bytes per triangle (normal, three float32 vertices,
// attribute word); the file must be exactly that long. ASCII: `solid` blocks of
// `facet normal ... outer loop vertex x y z ... endloop endfacet`, each block a
// part. Normals are ignored (the vertex order says which side is out) and equal
// positions are welded exactly, since STL stores every triangle's corners.
// A binary STL's positions stay float32 (model.hpp's Positions) and its
// triangles need no face sizes; an ASCII STL's decimals are read as doubles.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "library/corner_welding.hpp"
#include "library/huge_page_memory.hpp"
#include "readers/format_readers.hpp"
#include "readers/little_endian.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

constexpr uint64_t kBinaryHeaderBytes = 84;
constexpr uint64_t kBinaryTriangleBytes = 50;

bool starts_with_solid(std::string_view bytes) {
    const std::string::size_type first = bytes.find_first_not_of(" \t\r\n");
    return first != std::string::npos && bytes.compare(first, 5, "solid") == 0;
}

// The triangles' corners as float32, as the file stores them (36 bytes a
// triangle, against the file's 50; in huge pages, not zeroed first), decoded
// in one pass over the mapping. file, when given, holds bytes and is let go
// as they are decoded, before the corners are welded. The welded positions
// stay float32 (12 bytes a vertex).
Model read_binary(std::string_view bytes, FileBytes* file, uint64_t triangle_count) {
    HugePageArray<float> corners(9 * triangle_count);
    const unsigned char* triangle =
        reinterpret_cast<const unsigned char*>(bytes.data()) + kBinaryHeaderBytes;
    float* corner = corners.data();
    // The file and its corners are not held whole at once: the pages decoded
    // are given back every kWindow triangles.
    constexpr uint64_t kWindow = uint64_t(1) << 18;
    for (uint64_t t = 0; t < triangle_count; ++t, triangle += kBinaryTriangleBytes) {
        const unsigned char* coordinate = triangle + 12;  // after the normal
        for (int c = 0; c < 9; ++c, coordinate += 4) *corner++ = little_endian_f32(coordinate);
        if (file != nullptr && (t + 1) % kWindow == 0)
            file->drop_before(kBinaryHeaderBytes + (t + 1) * kBinaryTriangleBytes);
    }
    if (file != nullptr) file->release();
    Model model;
    Part& part = model.parts.emplace_back();  // triangles only: no face sizes
    std::vector<float> positions;
    part.indices = weld_corners(corners.data(), 3 * triangle_count, positions);
    model.positions = Positions(std::move(positions));
    return model;
}

Model read_ascii(std::string_view bytes) {
    Model model;
    // Every corner in file order; each part's indices number them until
    // they are welded, all parts at once (they share the positions).
    std::vector<double> soup;
    TextLines lines(bytes);
    Part* part = nullptr;
    // Where in a facet the reader is. Only `vertex` and `endloop` may appear
    // in a loop and one `outer loop` in a facet, so every corner read belongs
    // to the face its `endloop` records.
    bool in_facet = false;
    bool in_loop = false;
    bool facet_has_loop = false;
    uint32_t corners = 0;
    auto shown = [](std::string_view keyword) { return std::string(keyword.substr(0, 40)); };
    while (lines.next_line(false)) {
        std::string_view keyword;
        if (!lines.next_token(keyword)) continue;
        if (in_loop && keyword != "vertex" && keyword != "endloop") {
            lines.fail("'" + shown(keyword) + "' inside a facet's loop (expected 'vertex' or " +
                       "'endloop')");
        }
        if (keyword == "solid") {
            if (in_facet) lines.fail("'solid' inside a facet");
            part = &model.parts.emplace_back();
            std::string_view name;
            if (lines.next_token(name)) part->name = std::string(name);
        } else if (part == nullptr) {
            lines.fail("expected 'solid' before '" + shown(keyword) + "'");
        } else if (keyword == "facet") {
            if (in_facet) lines.fail("'facet' inside a facet (no 'endfacet' before it)");
            in_facet = true;
            facet_has_loop = false;
        } else if (keyword == "outer") {
            if (facet_has_loop) lines.fail("a second 'outer loop' in a facet");
            in_loop = true;
            facet_has_loop = in_facet;
            corners = 0;
        } else if (keyword == "vertex") {
            if (!in_loop) lines.fail("'vertex' outside an 'outer loop'");
            const double x = lines.expect_double("an x coordinate");
            const double y = lines.expect_double("a y coordinate");
            const double z = lines.expect_double("a z coordinate");
            part->indices.push_back(uint32_t(soup.size() / 3));
            soup.insert(soup.end(), {x, y, z});
            ++corners;
        } else if (keyword == "endloop") {
            if (!in_loop) lines.fail("'endloop' without 'outer loop'");
            part->face_sizes.push_back(corners);  // fewer than 3: the library names it
            in_loop = false;
        } else if (keyword == "endfacet") {
            in_facet = false;
        } else if (keyword == "endsolid") {
            if (in_facet) lines.fail("'endsolid' inside a facet");
            part = nullptr;
        } else {
            lines.fail("unexpected '" + shown(keyword) + "' in an ASCII STL");
        }
    }
    if (in_loop || in_facet) lines.fail("the file ends inside a facet");
    std::vector<double> positions;
    const std::vector<uint32_t> vertex_of = weld_corners(soup.data(), soup.size() / 3, positions);
    model.positions = Positions(std::move(positions));
    for (Part& each : model.parts)
        for (uint32_t& index : each.indices) index = vertex_of[index];
    return model;
}

Model read_stl_from(std::string_view bytes, FileBytes* file) {
    const uint64_t size = bytes.size();
    uint64_t binary_count = 0;
    bool binary_size_matches = false;
    if (size >= kBinaryHeaderBytes) {
        binary_count = little_endian_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
        binary_size_matches = size == kBinaryHeaderBytes + kBinaryTriangleBytes * binary_count;
    }
    // Some binary exporters also begin their header with "solid": the exact
    // binary size decides.
    if (starts_with_solid(bytes) && !binary_size_matches) return read_ascii(bytes);
    if (size < kBinaryHeaderBytes) {
        throw ReadError("not an STL file: " + std::to_string(size) +
                        " bytes, fewer than a binary STL header (84) and no 'solid' keyword");
    }
    if (!binary_size_matches) {
        const uint64_t expected = kBinaryHeaderBytes + kBinaryTriangleBytes * binary_count;
        throw ReadError("binary STL of the wrong length: its header says " +
                        std::to_string(binary_count) + " triangles, which take " +
                        std::to_string(expected) + " bytes, but the file has " +
                        std::to_string(size) +
                        (size < expected ? " (truncated)" : " (not an STL, or corrupt)"));
    }
    return read_binary(bytes, file, binary_count);
}

}  // namespace

Model read_stl(std::string_view bytes) { return read_stl_from(bytes, nullptr); }

Model read_stl(FileBytes file) { return read_stl_from(file.view(), &file); }

}  // namespace polymass_cli
