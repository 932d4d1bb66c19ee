// The thin-shell sheet against exact references: a flat plate and the
// surface of a box (closed forms: every coordinate and result a small
// rational), also far from the origin, rotated (integer edges along a 3-4-5
// direction) and at tiny and huge scales; a non-convex polygon face against
// its rectangles; a polyhedral sphere against an independent computation
// (the edge-midpoint rule, exact for quadratics over a triangle) and against
// the smooth spherical shell in the limit; and the wall bound against real
// walls whose mass properties are known exactly (a slab, a hollow box).
#include "core/thin_shell.hpp"

#include "check.hpp"
#include "test_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/principal_axes.hpp"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using polymass::core::thin_shell_moments;
using polymass::core::ThinShell;
using polymass_test::box_mesh;
using polymass_test::TestMesh;

constexpr double u = 0x1p-53;

struct Body {
    double mass = 0.0;
    Vector3d center = Vector3d::Zero();
    Matrix3d inertia = Matrix3d::Zero();  // about the centre
};

ThinShell sheet_of(const TestMesh& mesh, double thickness) {
    Eigen::AlignedBox3d box;
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i) box.extend(mesh.vertex(i));
    return thin_shell_moments(mesh.view(), thickness, box.center(), box.diagonal().norm());
}

// The computed body lies within its rounding bounds of the exact one (whose
// own evaluation in double adds a few roundings), and the bounds are small.
bool matches(const ThinShell& shell, const Body& exact, const char* label) {
    using namespace polymass::core;
    const RigidBody body = shell.moments.rigid_body();
    const ResultBounds bounds = shell.moments.result_bounds(body, principal_axes(body.inertia));
    const double scale = exact.inertia.cwiseAbs().maxCoeff();
    const double mass_error = std::abs(body.mass - exact.mass);
    const double center_error = (body.center_of_mass - exact.center).cwiseAbs().maxCoeff();
    const double inertia_error = (body.inertia - exact.inertia).cwiseAbs().maxCoeff();
    const double extent = std::sqrt(scale / exact.mass);
    const bool ok =
        mass_error <= bounds.volume + 4 * u * exact.mass &&
        center_error <= bounds.center_of_mass + 4 * u * exact.center.norm() &&
        inertia_error <= bounds.inertia + 16 * u * scale && bounds.volume <= 1e-12 * exact.mass &&
        bounds.center_of_mass <= 1e-12 * extent + 1e-15 * exact.center.norm() &&
        bounds.inertia <= 1e-12 * scale * (1.0 + exact.center.squaredNorm() / (extent * extent));
    if (!ok)
        std::printf("  %s: mass error %.3g (bound %.3g), centre %.3g (%.3g), inertia %.3g (%.3g)\n",
                    label, mass_error, bounds.volume, center_error, bounds.center_of_mass,
                    inertia_error, bounds.inertia);
    return ok;
}

// A uniform sheet of area density t over the box of sides a, b, c (its six
// faces), centred at the origin along the coordinate axes: ∫x², ∫y², ∫z²
// face by face, then I = diag(Syy + Szz, Sxx + Szz, Sxx + Syy).
Body box_surface(double a, double b, double c, double t) {
    const double xx = 2 * b * c * a * a / 4 + 2 * a * c * a * a / 12 + 2 * a * b * a * a / 12;
    const double yy = 2 * b * c * b * b / 12 + 2 * a * c * b * b / 4 + 2 * a * b * b * b / 12;
    const double zz = 2 * b * c * c * c / 12 + 2 * a * c * c * c / 12 + 2 * a * b * c * c / 4;
    Body body;
    body.mass = t * 2 * (a * b + b * c + c * a);
    body.inertia = t * Vector3d(yy + zz, xx + zz, xx + yy).asDiagonal();
    return body;
}

// A solid box of sides a, b, c (unit density), centred at the origin.
Body solid_box(double a, double b, double c) {
    Body body;
    body.mass = a * b * c;
    body.inertia =
        body.mass / 12 * Vector3d(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal();
    return body;
}

Body placed(Body body, const Matrix3d& rotation, const Vector3d& center, double scale) {
    body.mass *= scale * scale * scale;  // for a sheet: area s², thickness s
    body.center = center;
    body.inertia = std::pow(scale, 5) * rotation * body.inertia * rotation.transpose();
    return body;
}

void flat_plate() {
    std::printf("flat plate\n");
    const double a = 3, b = 2, t = 0.125;
    for (const bool triangles : {false, true}) {
        TestMesh plate;
        for (const Vector3d& p :
             {Vector3d(0, 0, 0), Vector3d(a, 0, 0), Vector3d(a, b, 0), Vector3d(0, b, 0)})
            plate.add_vertex(p);
        if (triangles) {
            plate.add_face({0, 1, 2});
            plate.add_face({2, 0, 3});  // the other turn: the sheet has no side
        } else {
            plate.add_face({0, 1, 2, 3});
        }
        Body exact;
        exact.mass = t * a * b;
        exact.center = {a / 2, b / 2, 0};
        exact.inertia = exact.mass / 12 * Vector3d(b * b, a * a, a * a + b * b).asDiagonal();
        const ThinShell shell = sheet_of(plate, t);
        CHECK(matches(shell, exact, triangles ? "plate (triangles)" : "plate (quad)"));
        CHECK(std::abs(shell.area - a * b) <= shell.area_bound + 4 * u * a * b);
        CHECK(shell.moments.volume == shell.moments.mass.volume);

        // A real plate: the slab of thickness t. Mass and centre agree
        // exactly; the inertia differs by the through-thickness term m t²/12.
        const Body slab = solid_box(a, b, t);
        const double inertia_gap = (slab.inertia - exact.inertia).cwiseAbs().maxCoeff();
        CHECK(std::abs(inertia_gap - exact.mass * t * t / 12) <= 1e-15);
        CHECK(inertia_gap <= shell.wall_bound.inertia);
    }
}

void box_surfaces() {
    std::printf("box surfaces (placed, rotated, scaled)\n");
    const double t = 0.25;
    // Edges (3,4,0), (−8,6,0), (0,0,15): a box 5 × 10 × 15 turned by the
    // 3-4-5 rotation, with integer corners (exact anywhere below 2^53).
    Matrix3d turn;
    turn << 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1;
    const Vector3d edges[2][3] = {{{5, 0, 0}, {0, 10, 0}, {0, 0, 15}},
                                  {{3, 4, 0}, {-8, 6, 0}, {0, 0, 15}}};
    const Vector3d offsets[] = {{0, 0, 0}, {1e6, -2e6, 3e6}, {1e8, 1e8, -1e8}};
    const double scales[] = {1.0, 0x1p-60, 0x1p60};
    int cases = 0, passed = 0;
    for (int rotated = 0; rotated < 2; ++rotated) {
        const Matrix3d rotation = rotated ? turn : Matrix3d::Identity();
        for (const Vector3d& offset : offsets) {
            for (const double scale : scales) {
                if (scale != 1.0 && offset.norm() > 0) continue;  // each on its own
                for (const bool triangles : {false, true}) {
                    const Vector3d* e = edges[rotated];
                    const TestMesh box = box_mesh(scale * offset, scale * e[0], scale * e[1],
                                                  scale * e[2], triangles);
                    const Vector3d center = scale * (offset + (e[0] + e[1] + e[2]) / 2);
                    const Body exact = placed(box_surface(5, 10, 15, t), rotation, center, scale);
                    ++cases;
                    passed += matches(sheet_of(box, scale * t), exact, "box surface");
                }
            }
        }
    }
    std::printf("  %d of %d placements within their rounding bounds of the closed form\n", passed,
                cases);
    CHECK(passed == cases);

    // The float instantiation reads the same small integers exactly.
    const TestMesh box = box_mesh({0, 0, 0}, edges[0][0], edges[0][1], edges[0][2], true);
    std::vector<float> narrow(box.coordinates.begin(), box.coordinates.end());
    auto view = polymass::core::MeshView<float, std::uint32_t>();
    view.positions.base = reinterpret_cast<const unsigned char*>(narrow.data());
    view.positions.stride = 3 * sizeof(float);
    view.vertex_count = box.vertex_count();
    view.indices.base = reinterpret_cast<const unsigned char*>(box.indices.data());
    view.index_count = box.indices.size();
    view.face_count = box.indices.size() / 3;
    const ThinShell narrow_shell = thin_shell_moments(view, t, Vector3d(2.5, 5, 7.5), 20.0);
    CHECK(
        matches(narrow_shell,
                placed(box_surface(5, 10, 15, t), Matrix3d::Identity(), Vector3d(2.5, 5, 7.5), 1.0),
                "float box surface"));
}

// Needs neither closure nor orientation: flipped faces change nothing, and a
// removed face takes away exactly its own part.
void open_and_unoriented() {
    std::printf("open and unoriented surfaces\n");
    const double t = 0.5;
    const TestMesh box = box_mesh({0, 0, 0}, {5, 0, 0}, {0, 10, 0}, {0, 0, 15}, false);
    TestMesh flipped = box;
    for (std::size_t face : {1u, 4u})
        std::reverse(flipped.indices.begin() + 4 * face, flipped.indices.begin() + 4 * face + 4);
    const ThinShell whole = sheet_of(box, t), turned = sheet_of(flipped, t);
    CHECK(std::abs(turned.area - whole.area) <= 2 * whole.area_bound);
    CHECK((turned.moments.about(Vector3d::Zero()).mass.second -
           whole.moments.about(Vector3d::Zero()).mass.second)
              .cwiseAbs()
              .maxCoeff() <= 1e-9);

    // Without the top (z = 15, the 5 × 10 face): an open box.
    TestMesh open = box;
    open.indices.erase(open.indices.begin() + 4, open.indices.begin() + 8);
    open.face_sizes.pop_back();
    const ThinShell shell = sheet_of(open, t);
    Body exact = box_surface(5, 10, 15, t);
    const double lid = t * 50;
    // The lid's part about the box's centre: z = 7.5 above it, plate inertia.
    const Matrix3d lid_inertia = lid / 12 * Vector3d(100, 25, 125).asDiagonal().toDenseMatrix() +
                                 lid * (7.5 * 7.5 * Matrix3d::Identity() -
                                        Vector3d(0, 0, 7.5) * Vector3d(0, 0, 7.5).transpose());
    const double mass = exact.mass - lid;
    const Vector3d shift(0, 0, -lid * 7.5 / mass);  // the centre moves down
    exact.inertia = exact.inertia - lid_inertia -
                    mass * (shift.squaredNorm() * Matrix3d::Identity() - shift * shift.transpose());
    exact.mass = mass;
    exact.center = Vector3d(2.5, 5, 7.5) + shift;
    CHECK(matches(shell, exact, "open box"));
}

// The L-shaped hexagon [0,2]×[0,1] ∪ [0,1]×[1,2], its fan started at every
// corner (the reflex one included), against its two rectangles.
void non_convex_face() {
    std::printf("non-convex polygon face\n");
    const Vector3d corners[6] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    // Rectangles [0,2]×[0,1] and [0,1]×[1,2]: area 3, centre (5/6, 5/6).
    Body exact;
    exact.mass = 3;
    exact.center = {5.0 / 6, 5.0 / 6, 0};
    // ∫x² = 8/3 + 1/3 = 3, ∫y² = 2/3 + 7/3 = 3, ∫xy = 1 + 3/4 = 7/4, about the origin.
    Matrix3d second;
    second << 3, 7.0 / 4, 0, 7.0 / 4, 3, 0, 0, 0, 0;
    const Matrix3d central = second - exact.mass * exact.center * exact.center.transpose();
    exact.inertia = central.trace() * Matrix3d::Identity() - central;
    int passed = 0;
    for (int start = 0; start < 6; ++start) {
        TestMesh face;
        for (int k = 0; k < 6; ++k) face.add_vertex(corners[(start + k) % 6]);
        face.add_face({0, 1, 2, 3, 4, 5});
        passed += matches(sheet_of(face, 1.0), exact, "L-shaped face");
    }
    CHECK(passed == 6);
}

// Integrals of 1, r, r rᵀ over a triangle by the edge-midpoint rule (exact for
// polynomials of degree 2), in long double: an independent reference.
struct Reference {
    long double mass = 0;
    long double first[3] = {};
    long double second[3][3] = {};

    void add(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2, const Vector3d& about) {
        long double q[3][3], e1[3], e2[3];
        for (int i = 0; i < 3; ++i) {
            q[0][i] = (long double)p0[i] - about[i];
            q[1][i] = (long double)p1[i] - about[i];
            q[2][i] = (long double)p2[i] - about[i];
            e1[i] = q[1][i] - q[0][i];
            e2[i] = q[2][i] - q[0][i];
        }
        const long double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                  e1[0] * e2[1] - e1[1] * e2[0]};
        const long double area = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / 2;
        mass += area;
        for (int k = 0; k < 3; ++k) {
            long double m[3];
            for (int i = 0; i < 3; ++i) m[i] = (q[k][i] + q[(k + 1) % 3][i]) / 2;
            for (int i = 0; i < 3; ++i) {
                first[i] += area / 3 * m[i];
                for (int j = 0; j < 3; ++j) second[i][j] += area / 3 * m[i] * m[j];
            }
        }
    }
};

// The octahedron's faces cut `level` times into four, corners pushed out to
// the sphere of radius r about `center`.
TestMesh sphere(int level, double r, const Vector3d& center) {
    std::vector<std::array<Vector3d, 3>> faces;
    const Vector3d axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5}) faces.push_back({axes[x], axes[y], axes[z]});
    for (int l = 0; l < level; ++l) {
        std::vector<std::array<Vector3d, 3>> finer;
        for (const auto& f : faces) {
            const Vector3d m01 = (f[0] + f[1]).normalized(), m12 = (f[1] + f[2]).normalized(),
                           m20 = (f[2] + f[0]).normalized();
            finer.push_back({f[0], m01, m20});
            finer.push_back({m01, f[1], m12});
            finer.push_back({m20, m12, f[2]});
            finer.push_back({m01, m12, m20});
        }
        faces.swap(finer);
    }
    TestMesh mesh;  // a soup: the sheet needs no shared corners
    for (const auto& f : faces)
        mesh.add_face({mesh.add_vertex(center + r * f[0]), mesh.add_vertex(center + r * f[1]),
                       mesh.add_vertex(center + r * f[2])});
    return mesh;
}

void spherical_shell() {
    std::printf("spherical shell\n");
    const double t = 1e-3;
    double previous_error = 0;
    for (int level = 3; level <= 5; ++level) {
        for (const Vector3d& center : {Vector3d(0, 0, 0), Vector3d(1e6, -3e6, 2e6)}) {
            const TestMesh mesh = sphere(level, 1.0, center);
            const ThinShell shell = sheet_of(mesh, t);
            // Against the independent reference, about the sphere's centre.
            Reference reference;
            for (std::size_t f = 0; f < mesh.indices.size(); f += 3)
                reference.add(mesh.vertex(mesh.indices[f]), mesh.vertex(mesh.indices[f + 1]),
                              mesh.vertex(mesh.indices[f + 2]), center);
            const auto about = shell.moments.about(center);
            double worst = std::abs(about.mass.volume - t * double(reference.mass)) /
                           (t * double(reference.mass));
            for (int i = 0; i < 3; ++i) {
                worst =
                    std::max(worst, std::abs(about.mass.first[i] - t * double(reference.first[i])) /
                                        (t * double(reference.mass)));
                worst = std::max(
                    worst, std::abs(about.mass.second[i] - t * double(reference.second[i][i])) /
                               (t * double(reference.mass)));
                worst = std::max(worst, std::abs(about.mass.products[i] -
                                                 t * double(reference.second[i][(i + 1) % 3])) /
                                            (t * double(reference.mass)));
            }
            // Far from the origin the corners themselves are rounded at 1e6:
            // both sides see the same rounded corners, so they still agree.
            CHECK(worst <= 1e-12);
            // Against the smooth shell: m = 4π r² t, I = 2/3 m r²; the
            // polyhedron's area falls short by O(edge²), so does the inertia.
            if (center.norm() == 0) {
                const double smooth_mass = 4 * M_PI * t;
                const auto body = shell.moments.rigid_body();
                const double error =
                    std::max(std::abs(body.mass - smooth_mass) / smooth_mass,
                             (body.inertia - 2.0 / 3 * smooth_mass * Matrix3d::Identity())
                                     .cwiseAbs()
                                     .maxCoeff() /
                                 (2.0 / 3 * smooth_mass));
                std::printf("  level %d (%zu triangles): %.3g from the smooth shell\n", level,
                            mesh.indices.size() / 3, error);
                if (previous_error > 0) CHECK(error < previous_error / 3.5);  // O(h²)
                previous_error = error;
            }
        }
    }
}

// The sheet against real walls: a hollow box whose wall of thickness t is
// centred on the box's surface (outer box a+t, inner a−t: mitred corners).
void wall_bounds() {
    std::printf("wall bound against hollow boxes\n");
    for (const double t : {0.5, 0.05, 0.005}) {
        for (const bool triangles : {false, true}) {
            const double a = 5, b = 10, c = 15;
            const TestMesh box =
                box_mesh({-a / 2, -b / 2, -c / 2}, {a, 0, 0}, {0, b, 0}, {0, 0, c}, triangles);
            const ThinShell shell = sheet_of(box, t);
            const Body outer = solid_box(a + t, b + t, c + t),
                       inner = solid_box(a - t, b - t, c - t);
            const double wall_mass = outer.mass - inner.mass;
            const Matrix3d wall_inertia = outer.inertia - inner.inertia;
            const auto body = shell.moments.rigid_body();
            const double mass_error = std::abs(body.mass - wall_mass);
            const double inertia_error = (body.inertia - wall_inertia).cwiseAbs().maxCoeff();
            CHECK(mass_error <= shell.wall_bound.volume);
            CHECK(inertia_error <= shell.wall_bound.inertia);
            CHECK(body.center_of_mass.cwiseAbs().maxCoeff() <=
                  shell.wall_bound.center_of_mass + 1e-12);
            std::printf(
                "  t = %g, %s: mass off by %.3g (bound %.3g), inertia by %.3g (bound %.3g)\n", t,
                triangles ? "triangles" : "quads", mass_error, shell.wall_bound.volume,
                inertia_error, shell.wall_bound.inertia);
        }
    }
}

}  // namespace

int main() {
    std::printf("thin shell:\n");
    flat_plate();
    box_surfaces();
    open_and_unoriented();
    non_convex_face();
    spherical_shell();
    wall_bounds();
    return polymass_test::finish("test_thin_shell");
}
