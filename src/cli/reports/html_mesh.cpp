#include "reports/html_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace polymass_cli {
namespace {

struct Triangles {
    std::vector<uint32_t> corners;  // three vertex numbers each
    std::vector<uint32_t> faces;    // the face each comes from
};

bool drawable(const Model& model, uint32_t vertex) {
    if (vertex >= model.vertex_count()) return false;
    const std::array<double, 3> p = model.positions.vertex(vertex);
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Each face with three or more drawable corners as a fan of triangles.
Triangles fan_triangles(const Model& model, const Part& part) {
    Triangles triangles;
    size_t start = 0;
    for (size_t face = 0; face < part.face_count(); ++face) {
        const uint32_t size = part.face_size(face);
        const uint32_t* corner = &part.indices[start];
        start += size;
        if (size < 3 ||
            !std::all_of(corner, corner + size, [&](uint32_t v) { return drawable(model, v); }))
            continue;
        for (uint32_t k = 1; k + 1 < size; ++k) {
            triangles.corners.insert(triangles.corners.end(),
                                     {corner[0], corner[k], corner[k + 1]});
            triangles.faces.push_back(uint32_t(face));
        }
    }
    return triangles;
}

struct Box {
    std::array<double, 3> min{}, max{};
};

Box bounds(const Model& model, const Triangles& triangles) {
    Box box;
    box.min.fill(std::numeric_limits<double>::infinity());
    box.max.fill(-std::numeric_limits<double>::infinity());
    for (const uint32_t v : triangles.corners) {
        for (int axis = 0; axis < 3; ++axis) {
            const double x = model.positions[3 * size_t(v) + axis];
            box.min[axis] = std::min(box.min[axis], x);
            box.max[axis] = std::max(box.max[axis], x);
        }
    }
    if (triangles.corners.empty()) box.min = box.max = {0.0, 0.0, 0.0};
    return box;
}

// Vertex clustering: every vertex moved to the first vertex of its cell of a
// grid of cells of side cell; triangles whose corners fall in fewer than
// three cells are dropped.
Triangles clustered(const Model& model, const Triangles& triangles, const Box& box, double cell) {
    std::unordered_map<uint64_t, uint32_t> first_of_cell;
    std::unordered_map<uint32_t, uint32_t> representative;
    auto cluster = [&](uint32_t v) {
        const auto found = representative.find(v);
        if (found != representative.end()) return found->second;
        uint64_t key = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const double x = model.positions[3 * size_t(v) + axis];
            key = key * 2097152u + uint64_t(std::floor((x - box.min[axis]) / cell)) % 2097152u;
        }
        const uint32_t first = first_of_cell.emplace(key, v).first->second;
        representative.emplace(v, first);
        return first;
    };
    Triangles kept;
    for (size_t t = 0; t < triangles.faces.size(); ++t) {
        const uint32_t a = cluster(triangles.corners[3 * t]);
        const uint32_t b = cluster(triangles.corners[3 * t + 1]);
        const uint32_t c = cluster(triangles.corners[3 * t + 2]);
        if (a == b || b == c || a == c) continue;
        kept.corners.insert(kept.corners.end(), {a, b, c});
        kept.faces.push_back(triangles.faces[t]);
    }
    return kept;
}

// The finest grid whose clustering leaves at most kMaxShownTriangles: a
// surface's triangle count falls as the square of the cell's size.
Triangles decimated(const Model& model, const Triangles& triangles, const Box& box) {
    double extent = 0.0;
    for (int axis = 0; axis < 3; ++axis) extent = std::max(extent, box.max[axis] - box.min[axis]);
    // A mesh of one point (every vertex in one place) is one cell.
    double cell = (extent > 0.0 ? extent : 1.0) / std::sqrt(double(kMaxShownTriangles) / 4.0);
    Triangles kept = clustered(model, triangles, box, cell);
    while (kept.faces.size() > kMaxShownTriangles) {
        cell *= std::max(1.1, std::sqrt(double(kept.faces.size()) / kMaxShownTriangles));
        kept = clustered(model, triangles, box, cell);
    }
    return kept;
}

}  // namespace

Json mesh_view(HtmlPage& page, const Model& model, const Part& part,
               const std::vector<uint32_t>& shell_of_face, const Located& located) {
    Triangles triangles = fan_triangles(model, part);
    const uint64_t triangle_count = triangles.faces.size();
    const Box box = bounds(model, triangles);
    const bool decimate = triangle_count > kMaxShownTriangles;
    if (decimate) triangles = decimated(model, triangles, box);

    std::array<double, 3> origin{};
    for (int axis = 0; axis < 3; ++axis) origin[axis] = 0.5 * (box.min[axis] + box.max[axis]);
    // The corners renumbered in the order the triangles first use them.
    std::unordered_map<uint32_t, uint32_t> shown;
    std::vector<float> positions;
    for (uint32_t& corner : triangles.corners) {
        const auto [at, added] = shown.emplace(corner, uint32_t(shown.size()));
        if (added) {
            for (int axis = 0; axis < 3; ++axis)
                positions.push_back(
                    float(model.positions[3 * size_t(corner) + axis] - origin[axis]));
        }
        corner = at->second;
    }

    Json view = Json::object();
    view["origin"] = json_numbers(origin.data(), 3);
    view["vertices"] = model.vertex_count();
    view["faces"] = part.face_count();
    view["triangle_count"] = triangle_count;
    view["shown_triangles"] = triangles.faces.size();
    view["decimated"] = decimate;
    view["positions"] = page.add_floats(positions);
    view["triangles"] = page.add_uint32s(triangles.corners);
    view["triangle_faces"] = page.add_uint32s(triangles.faces);
    if (!shell_of_face.empty()) view["face_shells"] = page.add_uint32s(shell_of_face);

    std::vector<size_t> face_start(part.face_count() + 1, 0);
    for (size_t face = 0; face < part.face_count(); ++face)
        face_start[face + 1] = face_start[face] + part.face_size(face);
    Json faces = Json::object();
    std::vector<uint64_t> vertices = located.vertices;
    for (const uint64_t face : located.faces) {
        if (face >= part.face_count()) continue;
        const std::vector<uint32_t> corners(part.indices.begin() + face_start[face],
                                            part.indices.begin() + face_start[face + 1]);
        faces[std::to_string(face)] = corners;
        vertices.insert(vertices.end(), corners.begin(), corners.end());
    }
    Json points = Json::object();
    for (const uint64_t v : vertices) {
        if (v >= model.vertex_count()) continue;
        const std::array<double, 3> p = model.positions.vertex(v);
        const double relative[3] = {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
        points[std::to_string(v)] = json_numbers(relative, 3);
    }
    view["located_faces"] = faces;
    view["located_vertices"] = points;
    return view;
}

}  // namespace polymass_cli
