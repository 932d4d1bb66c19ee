// The exact convex hull: of convex solids it is the solid (same volume
// integrals as the solid path gives the solid itself); of an L-shaped prism
// the pentagonal prism known by construction; degenerate inputs (too few
// distinct points, collinear, coplanar — also tilted and far from the origin
// — and NaN) give their status. Random clouds (uniform, on a sphere, on an
// integer grid with many coplanar points, near-coplanar by one ulp, far from
// the origin) are checked against properties the hull must have, each decided
// exactly: every input point inside or on it, every face turning outward with
// all hull vertices behind or on it, every edge shared by two faces in opposite
// directions, and Euler's V − E + F = 2.
#include "core/convex_hull.hpp"

#include "check.hpp"
#include "test_mesh.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory_resource>
#include <random>
#include <utility>
#include <vector>

#include "core/exact_predicates.hpp"
#include "core/mesh_integration.hpp"
#include "core/mesh_scan.hpp"

namespace {

using Eigen::Vector3d;
using polymass::core::ConvexHull;
using polymass::core::HullStatus;
using polymass::core::IntegrationResult;
using polymass::core::orient3d;
using polymass_test::box_mesh;
using polymass_test::TestMesh;

ConvexHull hull_of(const TestMesh& mesh) {
    const auto view = mesh.view();
    polymass::core::SerialTaskRunner serial;
    const auto scan = polymass::core::scan_mesh(view, std::pmr::get_default_resource(), serial);
    return polymass::core::convex_hull(view, scan, std::pmr::get_default_resource());
}

// A cloud of points as the corners of degenerate triangles (what the hull
// reads is the vertices the faces use).
TestMesh cloud(const std::vector<Vector3d>& points) {
    TestMesh mesh;
    for (const Vector3d& p : points) mesh.add_vertex(p);
    for (std::uint32_t i = 0; i < points.size(); ++i)
        mesh.add_face(
            {i, std::uint32_t((i + 1) % points.size()), std::uint32_t((i + 2) % points.size())});
    return mesh;
}

IntegrationResult integrate(const polymass::core::MeshView<double, std::uint32_t>& view,
                            const Vector3d& reference, double size) {
    polymass::core::IntegrationSettings settings;
    settings.reference = reference;
    settings.size = size;
    polymass::core::SerialTaskRunner serial;
    return polymass::core::integrate_mesh(view, settings, serial);
}

// The hull's volume integrals equal the solid's within both rounding bounds.
bool same_integrals(const TestMesh& solid, const ConvexHull& hull, const char* label) {
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < solid.vertex_count(); ++i) box.extend(solid.vertex(i));
    const IntegrationResult a = integrate(solid.view(), box.center(), box.diagonal().norm());
    const IntegrationResult b = integrate(hull.view(), box.center(), box.diagonal().norm());
    const double slack = 1e-300;
    const bool ok = std::abs(a.integrals.volume - b.integrals.volume) <=
                        a.bounds.volume + b.bounds.volume + slack &&
                    (a.integrals.first - b.integrals.first).cwiseAbs().maxCoeff() <=
                        a.bounds.first + b.bounds.first + slack &&
                    (a.integrals.second - b.integrals.second).cwiseAbs().maxCoeff() <=
                        a.bounds.second + b.bounds.second + slack &&
                    (a.integrals.products - b.integrals.products).cwiseAbs().maxCoeff() <=
                        a.bounds.second + b.bounds.second + slack &&
                    a.integrals.volume > 0;
    if (!ok)
        std::printf("  %s: volume %.17g (solid) vs %.17g (hull)\n", label, a.integrals.volume,
                    b.integrals.volume);
    return ok;
}

// The properties every hull has, each decided exactly; returns the failures.
int hull_faults(const std::vector<Vector3d>& points, const ConvexHull& hull) {
    int faults = 0;
    auto vertex = [&](std::uint32_t i) {
        return Vector3d(hull.coordinates[3 * i], hull.coordinates[3 * i + 1],
                        hull.coordinates[3 * i + 2]);
    };
    const std::size_t faces = hull.triangle_count();
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t f = 0; f < faces; ++f) {
        const std::uint32_t* t = &hull.indices[3 * f];
        const Vector3d a = vertex(t[0]), b = vertex(t[1]), c = vertex(t[2]);
        // Non-degenerate, and every input point behind or on it.
        faults += (b - a).cross(c - a).squaredNorm() == 0 && (a == b || b == c || c == a);
        for (const Vector3d& p : points) faults += orient3d(a, b, c, p) > 0;
        for (int e = 0; e < 3; ++e) ++edges[{t[e], t[(e + 1) % 3]}];
    }
    // Each directed edge once, its reverse once: closed, consistently turned.
    for (const auto& [edge, count] : edges) {
        const auto reverse = edges.find({edge.second, edge.first});
        faults += count != 1 || reverse == edges.end() || reverse->second != 1;
    }
    // Some face is strictly outward: a point strictly inside is behind all faces.
    const std::size_t v = hull.coordinates.size() / 3, e = edges.size() / 2;
    faults += long(v) - long(e) + long(faces) != 2;
    // Every hull vertex is one of the input points.
    for (std::uint32_t i = 0; i < v; ++i)
        faults += std::find(points.begin(), points.end(), vertex(i)) == points.end();
    return faults;
}

void convex_solids() {
    std::printf("hulls of convex solids\n");
    // Integer corners: exact at every offset below 2^53.
    const Vector3d offsets[] = {{0, 0, 0}, {1e6, 2e6, -3e6}, {1e8, -1e8, 1e8}};
    int cases = 0, passed = 0;
    for (const Vector3d& offset : offsets) {
        for (const bool triangles : {false, true}) {
            // A box, and the same box turned by the 3-4-5 rotation.
            const TestMesh boxes[] = {
                box_mesh(offset, {5, 0, 0}, {0, 10, 0}, {0, 0, 15}, triangles),
                box_mesh(offset, {3, 4, 0}, {-8, 6, 0}, {0, 0, 15}, triangles)};
            for (const TestMesh& box : boxes) {
                const ConvexHull hull = hull_of(box);
                ++cases;
                passed += hull.status == HullStatus::ok && hull.coordinates.size() == 24 &&
                          same_integrals(box, hull, "box");
            }
        }
        // A tetrahedron and an octahedron.
        TestMesh tetra;
        for (const Vector3d& p :
             {Vector3d(0, 0, 0), Vector3d(3, 0, 0), Vector3d(0, 4, 0), Vector3d(0, 0, 5)})
            tetra.add_vertex(p + offset);
        tetra.add_face({0, 2, 1});
        tetra.add_face({0, 1, 3});
        tetra.add_face({0, 3, 2});
        tetra.add_face({1, 2, 3});
        TestMesh octa;
        for (const Vector3d& p : {Vector3d(2, 0, 0), Vector3d(-2, 0, 0), Vector3d(0, 3, 0),
                                  Vector3d(0, -3, 0), Vector3d(0, 0, 4), Vector3d(0, 0, -4)})
            octa.add_vertex(p + offset);
        for (std::uint32_t x : {0u, 1u})
            for (std::uint32_t y : {2u, 3u})
                for (std::uint32_t z : {4u, 5u}) {
                    // Outward when (x, y, z) is a right-handed octant.
                    const bool right = (x == 0) == (y == 2) ? z == 4 : z == 5;
                    if (right)
                        octa.add_face({x, y, z});
                    else
                        octa.add_face({x, z, y});
                }
        for (const TestMesh* solid : {&tetra, &octa}) {
            const ConvexHull hull = hull_of(*solid);
            ++cases;
            passed += hull.status == HullStatus::ok && same_integrals(*solid, hull, "polytope");
        }
    }
    std::printf("  %d of %d convex solids: hull integrals equal the solid's\n", passed, cases);
    CHECK(passed == cases);
}

// The L-shaped prism's hull is the prism over the pentagon (0,0) (2,0) (2,1)
// (1,2) (0,2): volume 3.5.
void l_shape() {
    std::printf("hull of an L-shaped prism\n");
    for (const Vector3d& offset : {Vector3d(0, 0, 0), Vector3d(1e8, 1e8, 1e8)}) {
        const double l[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        TestMesh prism;
        for (int level = 0; level < 2; ++level)
            for (const auto& xy : l) prism.add_vertex(offset + Vector3d(xy[0], xy[1], level));
        prism.add_face({5, 4, 3, 2, 1, 0});
        prism.add_face({6, 7, 8, 9, 10, 11});
        for (std::uint32_t i = 0; i < 6; ++i) {
            const std::uint32_t j = (i + 1) % 6;
            prism.add_face({i, j, j + 6, i + 6});
        }
        const double p[5][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
        TestMesh pentagon;
        for (int level = 0; level < 2; ++level)
            for (const auto& xy : p) pentagon.add_vertex(offset + Vector3d(xy[0], xy[1], level));
        pentagon.add_face({4, 3, 2, 1, 0});
        pentagon.add_face({5, 6, 7, 8, 9});
        for (std::uint32_t i = 0; i < 5; ++i) {
            const std::uint32_t j = (i + 1) % 5;
            pentagon.add_face({i, j, j + 5, i + 5});
        }
        const ConvexHull hull = hull_of(prism);
        CHECK(hull.status == HullStatus::ok);
        CHECK(hull.coordinates.size() == 30);  // the reflex corner (1, 1) at both levels is inside
        CHECK(same_integrals(pentagon, hull, "L-shaped prism"));
        const IntegrationResult r = integrate(hull.view(), offset, 3.0);
        CHECK(std::abs(r.integrals.volume - 3.5) <= r.bounds.volume);
    }
}

void degenerate_inputs() {
    std::printf("degenerate inputs\n");
    auto status = [](const std::vector<Vector3d>& points) { return hull_of(cloud(points)).status; };
    const Vector3d far(1e8, -1e8, 1e8);
    CHECK(status({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) == HullStatus::too_few_points);
    CHECK(status({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}) ==
          HullStatus::too_few_points);
    CHECK(status({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}}) ==
          HullStatus::too_few_points);
    std::vector<Vector3d> line, plane, tilted;
    for (int i = 0; i < 50; ++i) {
        line.push_back(far + double(i % 7) * Vector3d(3, -1, 2) + double(i) * Vector3d(3, -1, 2));
        plane.push_back(Vector3d(i % 5, i / 5, 0));
        // The plane x + 2y + 3z = 6 through integer points, far away.
        const double x = i % 7, y = i / 7;
        tilted.push_back(far + Vector3d(3 * x, 3 * y, -x - 2 * y));
    }
    CHECK(status(line) == HullStatus::collinear);
    CHECK(status(plane) == HullStatus::coplanar);
    CHECK(status(tilted) == HullStatus::coplanar);
    // One ulp off the plane is a volume: exact predicates see it.
    tilted.back().z() = std::nextafter(tilted.back().z(), 0.0);
    const ConvexHull thin = hull_of(cloud(tilted));
    CHECK(thin.status == HullStatus::ok && hull_faults(tilted, thin) == 0);
    std::vector<Vector3d> with_nan = plane;
    with_nan[3].y() = std::numeric_limits<double>::quiet_NaN();
    CHECK(status(with_nan) == HullStatus::non_finite);
    CHECK(status({}) == HullStatus::too_few_points);
}

void random_clouds() {
    std::printf("random clouds\n");
    std::mt19937_64 random(20240610);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::normal_distribution<double> normal;
    std::uniform_int_distribution<int> grid(0, 4);
    int clouds = 0, faulty = 0;
    std::size_t triangles = 0;
    for (int kind = 0; kind < 5; ++kind) {
        for (const double offset : {0.0, 1e8}) {
            // The plane and the tiny cube stay at the origin: 1e8 would round them away.
            if (kind >= 3 && offset != 0.0) continue;
            std::vector<Vector3d> points;
            for (int i = 0; i < 400; ++i) {
                Vector3d p;
                switch (kind) {
                    case 0:  // uniform in a cube
                        p = {uniform(random), uniform(random), uniform(random)};
                        break;
                    case 1:  // on a sphere (almost all on the hull)
                        p = Vector3d(normal(random), normal(random), normal(random)).normalized();
                        break;
                    case 2:  // an integer grid: many coplanar and collinear points
                        p = Vector3d(grid(random), grid(random), grid(random));
                        break;
                    case 3:  // a plane, each point off it by at most one ulp
                        p = {double(grid(random)), double(grid(random)), 0.0};
                        if (i % 3 == 0) p.z() = i % 2 ? 0x1p-1074 : -0x1p-1074;
                        break;
                    default:  // a tiny cube
                        p = 0x1p-900 * Vector3d(uniform(random), uniform(random), uniform(random));
                        break;
                }
                points.push_back(p + Vector3d(offset, -offset, offset));
            }
            const ConvexHull hull = hull_of(cloud(points));
            ++clouds;
            const int faults = hull.status == HullStatus::ok ? hull_faults(points, hull) : 1;
            faulty += faults > 0;
            triangles += hull.triangle_count();
            if (faults > 0) std::printf("  kind %d offset %g: %d faults\n", kind, offset, faults);
        }
    }
    std::printf("  %d clouds of 400 points (%zu hull triangles), %d with a fault\n", clouds,
                triangles, faulty);
    CHECK(faulty == 0);
}

}  // namespace

int main() {
    std::printf("convex hull:\n");
    convex_solids();
    l_shape();
    degenerate_inputs();
    random_clouds();
    return polymass_test::finish("test_convex_hull");
}
