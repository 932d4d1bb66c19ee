// triangle_contact on configurations whose answer is known by construction
// (crossing, disjoint, a corner or an edge on the other face, edges meeting
// in a point, coplanar overlap, a shared corner with and without a fin
// through the other face), also moved far from the origin and scaled to tiny
// and huge sizes; then random integer triangles, checked against an
// independent exact computation of the two segments on the planes' common
// line and for invariance under swapping, rotating and reversing.
#include "core/triangle_contact.hpp"

#include "check.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <random>
#include <utility>

namespace {

using Eigen::Vector3d;
using polymass::core::Contact;
using polymass::core::is_degenerate;
using polymass::core::Triangle;
using polymass::core::triangle_contact;

const char* name(Contact c) {
    switch (c) {
        case Contact::none:
            return "none";
        case Contact::touching:
            return "touching";
        case Contact::crossing:
            return "crossing";
        case Contact::coinciding:
            return "coinciding";
    }
    return "?";
}

Triangle rotated(Triangle t, int k) {
    for (int i = 0; i < k; ++i) t = {t[1], t[2], t[0]};
    return t;
}

Triangle reversed(Triangle t) {
    std::swap(t[1], t[2]);
    return t;
}

// The answer must not depend on which triangle comes first, on the corner the
// triangles start at (except the shared corner, which stays first), or on
// their orientations but through whether they face the same way (expected)
// or not (expected_opposite; the same for triangles in two planes). Returns
// the number of variants that disagree.
int variants_disagreeing(const Triangle& p, const Triangle& q, bool shared, Contact expected,
                         Contact expected_opposite) {
    int wrong = 0;
    const int rotations = shared ? 1 : 3;
    for (int rp = 0; rp < rotations; ++rp) {
        for (int rq = 0; rq < rotations; ++rq) {
            for (int flip = 0; flip < 4; ++flip) {
                Triangle a = rotated(p, rp), b = rotated(q, rq);
                if (flip & 1) a = reversed(a);
                if (flip & 2) b = reversed(b);
                const Contact want = flip == 1 || flip == 2 ? expected_opposite : expected;
                wrong += triangle_contact(a, b, shared) != want;
                wrong += triangle_contact(b, a, shared) != want;
            }
        }
    }
    return wrong;
}

Vector3d v(double x, double y, double z) { return {x, y, z}; }

// Each configuration meets p = base with q; with one of them reversed the
// answer is `opposite` (only coplanar triangles' answers change).
struct Configuration {
    const char* what;
    Triangle q;
    bool shared;
    Contact expected;
    Contact opposite = expected;
};

// The triangle (0,0,0), (4,0,0), (0,4,0) in the plane z = 0.
const Triangle base = {v(0, 0, 0), v(4, 0, 0), v(0, 4, 0)};

const Configuration configurations[] = {
    {"crossing (a fin through the interior)",
     {v(1, 1, -1), v(2, 1, 1), v(1, 2, 1)},
     false,
     Contact::crossing},
    {"crossing through an edge of each",
     {v(2, 1, -1), v(0, 1, 1), v(6, 1, 1)},
     false,
     Contact::crossing},
    {"disjoint (moved away)", {v(11, 1, -1), v(12, 1, 1), v(11, 2, 1)}, false, Contact::none},
    {"disjoint (parallel planes)", {v(0, 0, 1), v(4, 0, 1), v(0, 4, 1)}, false, Contact::none},
    {"straddling, segments apart", {v(6, 1, -1), v(5, 1, 1), v(8, 1, 1)}, false, Contact::none},
    {"corner on the interior", {v(1, 1, 0), v(1, 1, 2), v(2, 1, 2)}, false, Contact::touching},
    {"corner on an edge", {v(2, 0, 0), v(2, -1, 2), v(3, -1, 2)}, false, Contact::touching},
    {"corner on the plane, outside", {v(3, 3, 0), v(3, 3, 2), v(4, 3, 2)}, false, Contact::none},
    {"edge lying on the face", {v(1, 1, 0), v(2, 1, 0), v(1, 1, 2)}, false, Contact::touching},
    {"edge on the plane crossing the boundary",
     {v(3, 3, 0), v(1, 1, 0), v(2, 2, 5)},
     false,
     Contact::touching},
    {"edge on the plane, outside", {v(5, 5, 0), v(6, 4, 0), v(5, 5, 2)}, false, Contact::none},
    {"edges crossing in a point", {v(2, 2, -1), v(2, 2, 1), v(5, 5, 0)}, false, Contact::touching},
    {"straddling, segments meeting in a point",
     {v(-1, -1, -1), v(1, 1, 1), v(-3, -3, 1)},
     false,
     Contact::touching},
    {"coplanar overlapping",
     {v(1, 1, 0), v(5, 1, 0), v(1, 5, 0)},
     false,
     Contact::coinciding,
     Contact::touching},
    {"coplanar, one inside the other",
     {v(1, 1, 0), v(2, 1, 0), v(1, 2, 0)},
     false,
     Contact::coinciding,
     Contact::touching},
    {"coplanar, the same triangle", base, false, Contact::coinciding, Contact::touching},
    {"coplanar, along the same edge from the other side",
     {v(4, 0, 0), v(4, 4, 0), v(0, 4, 0)},
     false,
     Contact::touching},
    {"coplanar, a corner on the other's edge",
     {v(2, 2, 0), v(6, 2, 0), v(2, 6, 0)},
     false,
     Contact::touching},
    {"coplanar, meeting at a corner",
     {v(4, 0, 0), v(6, 0, 0), v(4, 2, 0)},
     false,
     Contact::touching},
    {"coplanar disjoint", {v(5, 5, 0), v(9, 5, 0), v(5, 9, 0)}, false, Contact::none},
    {"coplanar disjoint, separated by an edge of q only",
     {v(-1, 6, 0), v(6, -2, 0), v(10, 10, 0)},
     false,
     Contact::none},
    {"shared corner, a fin through the face",
     {v(0, 0, 0), v(3, 1, -1), v(1, 3, 1)},
     true,
     Contact::crossing},
    {"shared corner, fin outside the face",
     {v(0, 0, 0), v(-3, -1, -1), v(-1, -3, 1)},
     true,
     Contact::none},
    {"shared corner, above the face", {v(0, 0, 0), v(1, 0, 1), v(0, 1, 1)}, true, Contact::none},
    {"shared corner, coplanar overlapping",
     {v(0, 0, 0), v(1, 2, 0), v(2, 1, 0)},
     true,
     Contact::none},
    {"same fin without the shared flag",
     {v(0, 0, 0), v(-3, -1, -1), v(-1, -3, 1)},
     false,
     Contact::touching},
    {"same corner above the face without the flag",
     {v(0, 0, 0), v(1, 0, 1), v(0, 1, 1)},
     false,
     Contact::touching},
};

struct Placement {
    const char* what;
    double scale;
    Vector3d offset;
};

void known_configurations() {
    const Placement placements[] = {
        {"as built", 1.0, v(0, 0, 0)},
        {"moved by 1e6", 1.0, v(1e6, -2e6, 3e6)},
        {"moved by 1e8", 1.0, v(1e8, 3e8, -2e8)},
        {"scaled by 2^-332 (1.1e-100)", std::ldexp(1.0, -332), v(0, 0, 0)},
        {"scaled by 2^332 (8.7e99)", std::ldexp(1.0, 332), v(0, 0, 0)},
        {"scaled by 2^-332 and moved by 1e8 x scale", std::ldexp(1.0, -332),
         v(1e8, 1e8, 1e8) * std::ldexp(1.0, -332)},
    };
    for (const Placement& place : placements) {
        int wrong = 0;
        for (const Configuration& c : configurations) {
            Triangle p = base, q = c.q;
            for (Vector3d& x : p) x = x * place.scale + place.offset;
            for (Vector3d& x : q) x = x * place.scale + place.offset;
            const Contact got = triangle_contact(p, q, c.shared);
            CHECK(got == c.expected);
            if (got != c.expected) {
                std::fprintf(stderr, "  %s, %s: got %s, expected %s\n", c.what, place.what,
                             name(got), name(c.expected));
            }
            const int disagreeing = variants_disagreeing(p, q, c.shared, c.expected, c.opposite);
            CHECK(disagreeing == 0);
            if (disagreeing)
                std::fprintf(stderr, "  %s, %s: %d variants disagree\n", c.what, place.what,
                             disagreeing);
            wrong += (got != c.expected) + disagreeing;
        }
        std::printf("  %zu known configurations %-44s all variants: %s\n",
                    std::size(configurations), place.what, wrong ? "FAILED" : "ok");
    }
}

void degenerate_triangles() {
    CHECK(is_degenerate({v(0, 0, 0), v(1, 1, 1), v(2, 2, 2)}));
    CHECK(is_degenerate({v(1, 2, 3), v(1, 2, 3), v(5, 0, 0)}));
    CHECK(is_degenerate(
        {v(1e8, 1e8, 1e8), v(1e8 + 1, 1e8 + 2, 1e8 + 3), v(1e8 + 2, 1e8 + 4, 1e8 + 6)}));
    CHECK(!is_degenerate(base));
    // Collinear but for one unit in the last place: not degenerate.
    CHECK(!is_degenerate({v(0.5, 0.5, 0.5), v(12, 12, 12), v(24, 24, std::nextafter(24.0, 25.0))}));
    CHECK(!is_degenerate({v(0, 0, 0), v(1, 0, 0), v(0, 0, 1)}));
    std::printf("  %-64s ok\n", "is_degenerate: collinear, coincident, one ulp off");
}

// An independent reference for two triangles that strictly straddle each
// other's planes (integer corners): the parameters along the planes' common
// line where the closed triangles meet it, as exact fractions.
using Int = std::int64_t;
using IntVector = Eigen::Matrix<Int, 3, 1>;

struct Fraction {
    Int numerator;
    Int denominator;  // > 0
};

bool less(const Fraction& a, const Fraction& b) {
    // Small integer corners: the products stay far below 2^63.
    return a.numerator * b.denominator < b.numerator * a.denominator;
}

// The interval of t = direction . x over the points x of t that lie on the
// plane with the given normal through `origin`.
std::pair<Fraction, Fraction> interval_on_line(const std::array<IntVector, 3>& t,
                                               const IntVector& normal, const IntVector& origin,
                                               const IntVector& direction) {
    std::array<Int, 3> side;
    for (int i = 0; i < 3; ++i) side[i] = normal.dot(t[i] - origin);
    Fraction lo{0, 0}, hi{0, 0};
    const auto include = [&](const Fraction& f) {
        if (lo.denominator == 0 || less(f, lo)) lo = f;
        if (hi.denominator == 0 || less(hi, f)) hi = f;
    };
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        if (side[i] == 0) include({direction.dot(t[i]), 1});
        if ((side[i] < 0 && side[j] > 0) || (side[i] > 0 && side[j] < 0)) {
            Int denominator = side[i] - side[j];
            Int numerator =
                direction.dot(t[i]) * denominator + direction.dot(t[j] - t[i]) * side[i];
            if (denominator < 0) {
                denominator = -denominator;
                numerator = -numerator;
            }
            include({numerator, denominator});
        }
    }
    return {lo, hi};
}

bool strictly_straddles(const std::array<IntVector, 3>& t, const IntVector& normal,
                        const IntVector& origin) {
    bool above = false, below = false;
    for (const IntVector& x : t) {
        const Int side = normal.dot(x - origin);
        above = above || side > 0;
        below = below || side < 0;
    }
    return above && below;
}

void random_triangles() {
    std::mt19937_64 random(9);
    std::uniform_int_distribution<int> coordinate(-2, 2);
    long pairs = 0, shared_pairs = 0, straddling = 0, disagreeing = 0, reference_wrong = 0;
    long seen[4] = {0, 0, 0, 0};
    while (pairs < 5000) {
        std::array<IntVector, 3> p, q;
        for (IntVector& x : p)
            x = IntVector(coordinate(random), coordinate(random), coordinate(random));
        for (IntVector& x : q)
            x = IntVector(coordinate(random), coordinate(random), coordinate(random));
        // A third of the pairs share their first corner; a fifth lie in
        // the plane z = 0 (coplanar: touching or coinciding).
        const bool shared = pairs % 3 == 0;
        if (shared) q[0] = p[0];
        if (pairs % 5 == 1)
            for (std::array<IntVector, 3>* t : {&p, &q})
                for (IntVector& x : *t) x.z() = 0;
        int common = 0;
        for (const IntVector& a : p) {
            for (const IntVector& b : q) common += a == b;
        }
        if (common != (shared ? 1 : 0)) continue;
        Triangle tp, tq;
        for (int i = 0; i < 3; ++i) {
            tp[i] = p[i].cast<double>();
            tq[i] = q[i].cast<double>();
        }
        if (is_degenerate(tp) || is_degenerate(tq)) continue;
        ++pairs;
        shared_pairs += shared;
        const Contact got = triangle_contact(tp, tq, shared);
        ++seen[static_cast<int>(got)];
        disagreeing += variants_disagreeing(tp, tq, shared, got,
                                            triangle_contact(tp, reversed(tq), shared)) != 0;

        const IntVector np = (p[1] - p[0]).cross(p[2] - p[0]);
        const IntVector nq = (q[1] - q[0]).cross(q[2] - q[0]);
        // Coinciding: in one plane, facing the same way, sharing no corner.
        const bool coplanar = np.cross(nq).isZero() && np.dot(q[0] - p[0]) == 0;
        if (got == Contact::coinciding) reference_wrong += !coplanar || np.dot(nq) < 0 || shared;
        if (!strictly_straddles(p, nq, q[0]) || !strictly_straddles(q, np, p[0])) {
            // Not straddling: never crossing.
            reference_wrong += got == Contact::crossing;
            continue;
        }
        ++straddling;
        const IntVector direction = np.cross(nq);
        const auto [p_lo, p_hi] = interval_on_line(p, nq, q[0], direction);
        const auto [q_lo, q_hi] = interval_on_line(q, np, p[0], direction);
        const Fraction lo = less(p_lo, q_lo) ? q_lo : p_lo;
        const Fraction hi = less(p_hi, q_hi) ? p_hi : q_hi;
        Contact expected = Contact::none;
        if (less(lo, hi))
            expected = Contact::crossing;
        else if (!less(hi, lo) && !shared)
            expected = Contact::touching;
        reference_wrong += got != expected;
    }
    CHECK(disagreeing == 0);
    CHECK(reference_wrong == 0);
    // The sample must exercise every answer, or it proves little.
    CHECK(seen[0] > 0 && seen[1] > 0 && seen[2] > 0 && seen[3] > 0);
    std::printf(
        "  %ld random integer pairs (%ld sharing a corner, %ld straddling): "
        "%ld none, %ld touching, %ld crossing, %ld coinciding; %ld inconsistent under "
        "symmetries, %ld differ from the reference\n",
        pairs, shared_pairs, straddling, seen[0], seen[1], seen[2], seen[3], disagreeing,
        reference_wrong);
}

}  // namespace

int main() {
    std::printf("triangle contact:\n");
    degenerate_triangles();
    known_configurations();
    random_triangles();
    return polymass_test::finish("test_triangle_contact");
}
