// A mesh as the --html page draws it: its faces as triangles (fans from each
// polygon's first corner) over the vertices they use, and, past
// kMaxShownTriangles, a coarser surface made by clustering vertices on a grid
// (the page says so, with both counts); the vertices and faces the findings
// name (by the file's numbers) given exactly beside it.
#pragma once

#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "reports/html_page.hpp"

namespace polymass_cli {

// Past this many triangles a mesh is drawn decimated: a page of 2e5
// triangles opens in about a second in a software-rendered browser.
inline constexpr uint64_t kMaxShownTriangles = 200000;

// What the page must draw exactly: the vertices and faces findings name.
struct Located {
    std::vector<uint64_t> vertices;
    std::vector<uint64_t> faces;
};

// The mesh object of the page's data, its arrays added to page:
// "origin" (the bounding box's centre, subtracted from every position so
// that a part far from the origin keeps its detail in floats), "positions"
// (the shown triangles' corners), "triangles" and "triangle_faces" (array
// ids), "vertices", "faces", "triangle_count", "shown_triangles",
// "decimated", "face_shells" (an array id: each face's shell) when
// shell_of_face is given, "located_faces" (each located face's vertex
// numbers) and "located_vertices" (the position of each vertex they and
// located.vertices name).
Json mesh_view(HtmlPage& page, const Model& model, const Part& part,
               const std::vector<uint32_t>& shell_of_face, const Located& located);

}  // namespace polymass_cli
