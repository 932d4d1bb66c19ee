// Wavefront OBJ: `v x y z [w]` vertices and `f` polygon faces whose corners
// are `v`, `v/vt`, `v//vn` or `v/vt/vn`, 1-based, negative meaning relative to
// the vertices read so far; a `\` ending a line continues it on the next.
// Each `o` starts a part; groups (`g`), materials, texture coordinates,
// normals and lines are not part of the solid.
#include <cstdint>
#include <string>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

constexpr uint64_t kSmallestVertexLine = 8;  // "v 0 0 0\n"

// The 0-based vertex a face corner token names, or kIndexOutOfRange.
uint32_t corner_vertex(std::string_view corner, uint64_t vertices_so_far, const TextLines& lines) {
    const std::string_view vertex_field = corner.substr(0, corner.find('/'));
    int64_t index = 0;
    if (!parse_integer(vertex_field, index)) {
        lines.fail("face corner '" + std::string(corner.substr(0, 40)) +
                   "' does not start with a vertex number");
    }
    // 1-based; negative counts back from the last vertex read; 0 is no vertex.
    const int64_t zero_based =
        index > 0 ? index - 1 : static_cast<int64_t>(vertices_so_far) + index;
    if (index == 0 || zero_based < 0 || zero_based >= static_cast<int64_t>(kIndexOutOfRange)) {
        return kIndexOutOfRange;
    }
    return static_cast<uint32_t>(zero_based);
}

}  // namespace

Model read_obj(std::string_view bytes) {
    Model model;
    model.parts.emplace_back();
    TextLines lines(bytes);
    while (lines.next_line(true)) {
        std::string_view keyword;
        if (!lines.next_token(keyword)) continue;
        if (keyword == "v") {
            for (const char* axis : {"an x coordinate", "a y coordinate", "a z coordinate"}) {
                model.positions.as_doubles().push_back(lines.expect_double(axis));
            }
        } else if (keyword == "f") {
            Part& part = model.parts.back();
            // The vertices the rest of the file can hold (a `v` line takes
            // at least 8 bytes) bound the face's corners as they are read,
            // not once they fill the memory.
            const uint64_t most_corners =
                most_face_corners((bytes.size() - lines.rest_of_line()) / kSmallestVertexLine);
            uint32_t corners = 0;
            std::string_view corner;
            while (lines.next_token(corner)) {
                // A backslash ending a line continues the face on the next one.
                if (corner == "\\") {
                    std::string_view after;
                    if (lines.next_token(after)) lines.fail("a '\\' in the middle of a face");
                    if (!lines.next_line(true)) break;
                    continue;
                }
                if (++corners > most_corners) {
                    lines.fail("a face of more than " + std::to_string(most_corners) +
                               " corners, which a file of " + std::to_string(bytes.size()) +
                               " bytes has not the vertices for: a polygon passes through a "
                               "vertex at most twice");
                }
                part.indices.push_back(corner_vertex(corner, model.vertex_count(), lines));
            }
            // A face of fewer than 3 corners is kept: the library names it.
            part.face_sizes.push_back(corners);
        } else if (keyword == "o") {
            std::string_view name;
            lines.next_token(name);
            if (!model.parts.back().face_sizes.empty()) model.parts.emplace_back();
            model.parts.back().name = std::string(name);
        }
    }
    return model;
}

}  // namespace polymass_cli
