// Object File Format (OFF, and its COFF/NOFF/CNOFF variants whose extra
// per-vertex columns are ignored): a header line, then
// "vertex_count face_count edge_count", the vertices, then each face as its
// vertex count followed by 0-based indices (and an optional colour).
#include <cstdint>
#include <string>
#include <vector>

#include "readers/format_readers.hpp"
#include "readers/mesh_reader.hpp"
#include "readers/text_lines.hpp"

namespace polymass_cli {
namespace {

// Advances to the next line holding a token and returns that token.
std::string_view first_token_of_next_line(TextLines& lines, const char* what) {
    std::string_view token;
    while (lines.next_line(true)) {
        if (lines.next_token(token)) return token;
    }
    lines.fail(std::string("the file ends before ") + what);
}

// A count from the header, checked against the size of the file so that a
// corrupt header cannot ask for an absurd allocation.
uint64_t header_count(TextLines& lines, const char* what, uint64_t file_size) {
    const int64_t count = lines.expect_integer(what);
    if (count < 0 || static_cast<uint64_t>(count) > file_size) {
        lines.fail(std::string("impossible ") + what + " " + std::to_string(count));
    }
    return static_cast<uint64_t>(count);
}

}  // namespace

Model read_off(std::string_view bytes) {
    TextLines lines(bytes);
    const std::string_view keyword = first_token_of_next_line(lines, "the OFF header");
    const std::string_view::size_type off_at = keyword.find("OFF");
    if (off_at == std::string_view::npos || keyword.find_first_not_of("CNST") < off_at) {
        lines.fail("not an OFF file: the first word is not OFF (or COFF, NOFF, ...)");
    }
    // The counts may follow the keyword on the same line, the first even
    // without a space ("OFF8 6 0").
    std::string_view token = keyword.substr(off_at + 3);
    int64_t vertex_count_value = 0;
    if (!token.empty()) {
        if (!parse_integer(token, vertex_count_value)) {
            lines.fail("not an OFF file: the first word is not OFF (or COFF, NOFF, ...)");
        }
    } else if (lines.next_token(token)) {
        if (!parse_integer(token, vertex_count_value)) lines.fail("expected the vertex count");
    } else {
        token = first_token_of_next_line(lines, "the vertex and face counts");
        if (!parse_integer(token, vertex_count_value)) lines.fail("expected the vertex count");
    }
    if (vertex_count_value < 0 || static_cast<uint64_t>(vertex_count_value) > bytes.size()) {
        lines.fail("impossible vertex count " + std::to_string(vertex_count_value));
    }
    const uint64_t vertex_count = static_cast<uint64_t>(vertex_count_value);
    const uint64_t face_count = header_count(lines, "face count", bytes.size());

    Model model;
    std::vector<double>& positions = model.positions.as_doubles();
    positions.reserve(3 * vertex_count);
    for (uint64_t vertex = 0; vertex < vertex_count; ++vertex) {
        token = first_token_of_next_line(lines, "all the vertices are listed");
        double x = 0.0;
        if (!parse_double(token, x)) lines.fail("expected an x coordinate");
        positions.push_back(x);
        positions.push_back(lines.expect_double("a y coordinate"));
        positions.push_back(lines.expect_double("a z coordinate"));
    }
    Part& part = model.parts.emplace_back();
    part.face_sizes.reserve(face_count);
    for (uint64_t face = 0; face < face_count; ++face) {
        token = first_token_of_next_line(lines, "all the faces are listed");
        int64_t size = 0;
        if (!parse_integer(token, size) || size < 0 || static_cast<uint64_t>(size) > bytes.size()) {
            lines.fail("expected a face's vertex count");
        }
        for (int64_t corner = 0; corner < size; ++corner) {
            const int64_t index = lines.expect_integer("a vertex index");
            part.indices.push_back(index < 0 || index >= static_cast<int64_t>(kIndexOutOfRange)
                                       ? kIndexOutOfRange
                                       : static_cast<uint32_t>(index));
        }
        part.face_sizes.push_back(static_cast<uint32_t>(size));
    }
    return model;
}

}  // namespace polymass_cli
