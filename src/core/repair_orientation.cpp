// Turning faces and shells the right way: repair's orientation steps.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "repair_surface.hpp"

namespace polymass::core {
namespace {

constexpr std::uint32_t kUnset = UINT32_MAX;

// How many times the triangles [first, last) of `order` wind around `point`:
// their solid angles (Van Oosterom and Strackee) over 4π.
double winding_number(const RepairSurface& surface, const std::uint32_t* first,
                      const std::uint32_t* last, const Eigen::Vector3d& point) {
    double sum = 0.0;
    for (const std::uint32_t* t = first; t != last; ++t) {
        const auto& c = surface.triangles[*t].corners;
        const Eigen::Vector3d a = surface.point(c[0]) - point, b = surface.point(c[1]) - point,
                              d = surface.point(c[2]) - point;
        const double la = a.norm(), lb = b.norm(), ld = d.norm();
        const double numerator = a.dot(b.cross(d));
        const double denominator = la * lb * ld + a.dot(b) * ld + b.dot(d) * la + d.dot(a) * lb;
        sum += 2.0 * std::atan2(numerator, denominator);
    }
    return sum / (4.0 * M_PI);
}

}  // namespace

bool orient_pieces(RepairSurface& surface, const std::pmr::vector<EdgeLink>& links,
                   std::pmr::vector<std::uint32_t>& component, std::size_t& component_count,
                   RepairReport& report, std::pmr::memory_resource* memory) {
    const std::size_t n = surface.triangles.size();
    // The links as adjacency lists (compressed rows).
    std::pmr::vector<std::uint32_t> offset(n + 1, 0, memory);
    for (const EdgeLink& link : links) {
        ++offset[link.first + 1];
        ++offset[link.second + 1];
    }
    for (std::size_t t = 0; t < n; ++t) offset[t + 1] += offset[t];
    std::pmr::vector<std::pair<std::uint32_t, bool>> neighbours(offset[n], memory);
    {
        std::pmr::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1, memory);
        for (const EdgeLink& link : links) {
            neighbours[fill[link.first]++] = {link.second, link.same_direction};
            neighbours[fill[link.second]++] = {link.first, link.same_direction};
        }
    }
    component.assign(n, kUnset);
    std::pmr::vector<char> flip(n, 0, memory);
    std::pmr::vector<std::uint32_t> queue(memory);
    component_count = 0;
    for (std::uint32_t seed = 0; seed < n; ++seed) {
        if (component[seed] != kUnset) continue;
        const auto piece = std::uint32_t(component_count++);
        component[seed] = piece;
        queue.assign(1, seed);
        while (!queue.empty()) {
            const std::uint32_t t = queue.back();
            queue.pop_back();
            for (std::uint32_t i = offset[t]; i < offset[t + 1]; ++i) {
                const auto [u, same] = neighbours[i];
                const char wanted = char(flip[t] ^ char(same));
                if (component[u] == kUnset) {
                    component[u] = piece;
                    flip[u] = wanted;
                    queue.push_back(u);
                } else if (flip[u] != wanted) {
                    report.failure = RepairFailure::non_orientable;
                    report.failed_face = surface.triangles[t].face;
                    return false;
                }
            }
        }
    }
    for (std::size_t t = 0; t < n; ++t)
        if (flip[t]) surface.triangles[t].turn();
    return true;
}

void turn_shells(RepairSurface& surface, const std::pmr::vector<std::uint32_t>& component,
                 std::size_t component_count, RepairReport& report,
                 std::pmr::memory_resource* memory) {
    const auto& triangles = surface.triangles;
    // The triangles of each piece together (counting sort).
    std::pmr::vector<std::uint32_t> start(component_count + 1, 0, memory);
    for (std::uint32_t c : component) ++start[c + 1];
    for (std::size_t c = 0; c < component_count; ++c) start[c + 1] += start[c];
    std::pmr::vector<std::uint32_t> members(triangles.size(), memory);
    {
        std::pmr::vector<std::uint32_t> fill(start.begin(), start.end() - 1, memory);
        for (std::uint32_t t = 0; t < triangles.size(); ++t) members[fill[component[t]]++] = t;
    }
    struct Piece {
        double volume = 0.0;
        Eigen::AlignedBox3d box;
        // Just inside the piece, below the centroid of its largest triangle:
        // a point on the piece itself could lie on a piece it touches.
        Eigen::Vector3d sample = Eigen::Vector3d::Zero();
        Eigen::Vector3d inward = Eigen::Vector3d::Zero();  // that triangle's normal, unit
    };
    std::pmr::vector<Piece> pieces(component_count, memory);
    for (std::size_t c = 0; c < component_count; ++c) {
        Piece& piece = pieces[c];
        double largest = -1.0;
        for (std::uint32_t i = start[c]; i < start[c + 1]; ++i) {
            const auto& corners = triangles[members[i]].corners;
            const Eigen::Vector3d a = surface.point(corners[0]) - surface.reference,
                                  b = surface.point(corners[1]) - surface.reference,
                                  d = surface.point(corners[2]) - surface.reference;
            piece.volume += a.dot(b.cross(d)) / 6.0;
            for (std::uint32_t id : corners) piece.box.extend(surface.point(id));
            const double area = (b - a).cross(d - a).norm();
            if (area > largest) {
                largest = area;
                piece.sample = surface.reference + (a + b + d) / 3.0;
                piece.inward = -(b - a).cross(d - a) / area;
            }
        }
        // The normal points out of the region the piece encloses when its
        // volume is positive. A step of 1e-6 of the piece's size stays inside
        // all but pieces thinner than that.
        const double step = 1e-6 * piece.box.diagonal().norm();
        piece.sample += (piece.volume < 0.0 ? -step : step) * piece.inward;
    }
    // A piece inside an odd number of others is a cavity: negative volume.
    for (std::size_t c = 0; c < component_count; ++c) {
        std::size_t depth = 0;
        for (std::size_t other = 0; other < component_count; ++other)
            if (other != c && pieces[other].box.contains(pieces[c].sample))
                depth +=
                    std::abs(winding_number(surface, &members[start[other]],
                                            &members[start[other + 1]], pieces[c].sample)) > 0.5;
        const bool cavity = depth % 2 == 1;
        const double volume = pieces[c].volume;
        if (volume != 0.0 && (volume < 0.0) != cavity)
            for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
                surface.triangles[members[i]].turn();
    }
    // What changed, face by face: a piece most of whose faces were turned
    // was inside out; the faces turned against their piece's majority were
    // the flipped ones.
    std::pmr::vector<std::uint32_t> reoriented(memory), turned_first_faces(memory);
    for (std::size_t c = 0; c < component_count; ++c) {
        std::size_t input_faces = 0, turned = 0;
        std::uint32_t first_face = kCapFace;
        for (std::uint32_t i = start[c]; i < start[c + 1]; ++i) {
            const RepairTriangle& t = triangles[members[i]];
            if (t.face == kCapFace) continue;
            ++input_faces;
            turned += t.turned;
            first_face = std::min(first_face, t.face);
        }
        const bool piece_turned = 2 * turned > input_faces;
        if (piece_turned) turned_first_faces.push_back(first_face);
        for (std::uint32_t i = start[c]; i < start[c + 1]; ++i) {
            const RepairTriangle& t = triangles[members[i]];
            if (t.face != kCapFace && t.turned != piece_turned) reoriented.push_back(t.face);
        }
    }
    record_faces(reoriented, report.reoriented_faces);
    record_faces(turned_first_faces, report.turned_shells);
}

}  // namespace polymass::core
