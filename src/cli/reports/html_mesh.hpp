// A mesh as the --html page draws it: the file's vertices (numbered as the
// file numbers them, so that the findings' vertex numbers name them), its
// faces as triangles (fans from each polygon's first corner), and, past
// kMaxShownTriangles, a coarser surface made by clustering vertices on a grid
// (the page says so, with both counts).
#pragma once

#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "reports/html_page.hpp"

namespace polymass_cli {

// Past this many triangles a mesh is drawn decimated: a page of 2e5
// triangles opens in about a second in a software-rendered browser.
inline constexpr uint64_t kMaxShownTriangles = 200000;

// The mesh object of the page's data, its arrays added to page:
// "origin" (the bounding box's centre, subtracted from the float positions
// so that a part far from the origin keeps its detail), "positions",
// "triangles" and "triangle_faces" (array ids), "vertices", "faces",
// "triangle_count", "shown_triangles", "decimated", and "face_shells" (an
// array id: each face's shell) when shell_of_face is given. located_faces:
// faces the page must draw exactly (the findings'), given under
// "located_faces" as their vertex numbers.
Json mesh_view(HtmlPage& page, const Model& model, const Part& part,
               const std::vector<uint32_t>& shell_of_face,
               const std::vector<uint64_t>& located_faces);

}  // namespace polymass_cli
