// orient3d, PlaneSide, certain_common_side and orient2d against an exact reference: every double is
// an integer times 2^-1074, so the determinants are evaluated here exactly with a small
// arbitrary-precision integer type on those integers. The inputs are chosen where double evaluation
// gets the sign wrong: coplanar (collinear) points perturbed by one unit in the last place, far
// from the origin, at tiny and huge scales.
#include "core/exact_predicates.hpp"

#include "check.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using polymass::core::certain_common_side;
using polymass::core::orient2d;
using polymass::core::orient3d;
using polymass::core::PlaneSide;

// Signed integer of any size: sign and magnitude in base 2^32, little-endian.
struct BigInt {
    bool negative = false;
    std::vector<std::uint32_t> limbs;

    void trim() {
        while (!limbs.empty() && limbs.back() == 0) limbs.pop_back();
        if (limbs.empty()) negative = false;
    }
    int sign() const { return limbs.empty() ? 0 : (negative ? -1 : 1); }
};

int compare_magnitude(const BigInt& a, const BigInt& b) {
    if (a.limbs.size() != b.limbs.size()) return a.limbs.size() < b.limbs.size() ? -1 : 1;
    for (std::size_t i = a.limbs.size(); i-- > 0;) {
        if (a.limbs[i] != b.limbs[i]) return a.limbs[i] < b.limbs[i] ? -1 : 1;
    }
    return 0;
}

BigInt add(const BigInt& a, const BigInt& b) {
    BigInt r;
    if (a.negative == b.negative) {
        r.negative = a.negative;
        std::uint64_t carry = 0;
        for (std::size_t i = 0; i < std::max(a.limbs.size(), b.limbs.size()) || carry; ++i) {
            std::uint64_t s = carry;
            if (i < a.limbs.size()) s += a.limbs[i];
            if (i < b.limbs.size()) s += b.limbs[i];
            r.limbs.push_back(static_cast<std::uint32_t>(s));
            carry = s >> 32;
        }
    } else {
        const bool a_larger = compare_magnitude(a, b) >= 0;
        const BigInt& big = a_larger ? a : b;
        const BigInt& small = a_larger ? b : a;
        r.negative = big.negative;
        std::int64_t borrow = 0;
        for (std::size_t i = 0; i < big.limbs.size(); ++i) {
            std::int64_t d = static_cast<std::int64_t>(big.limbs[i]) - borrow;
            if (i < small.limbs.size()) d -= small.limbs[i];
            borrow = d < 0 ? 1 : 0;
            r.limbs.push_back(static_cast<std::uint32_t>(d + (borrow << 32)));
        }
    }
    r.trim();
    return r;
}

BigInt negate(BigInt a) {
    if (a.sign() != 0) a.negative = !a.negative;
    return a;
}

BigInt subtract(const BigInt& a, const BigInt& b) { return add(a, negate(b)); }

BigInt multiply(const BigInt& a, const BigInt& b) {
    BigInt r;
    r.limbs.assign(a.limbs.size() + b.limbs.size(), 0);
    for (std::size_t i = 0; i < a.limbs.size(); ++i) {
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < b.limbs.size() || carry; ++j) {
            std::uint64_t t = r.limbs[i + j] + carry;
            if (j < b.limbs.size()) t += static_cast<std::uint64_t>(a.limbs[i]) * b.limbs[j];
            r.limbs[i + j] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
    }
    r.negative = a.negative != b.negative;
    r.trim();
    return r;
}

// x * 2^1074, an integer for every finite double.
BigInt scaled_integer(double x) {
    BigInt r;
    if (x == 0.0) return r;
    int exponent = 0;
    const double fraction = std::frexp(std::fabs(x), &exponent);
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
    int shift = exponent - 53 + 1074;
    if (shift < 0) {  // subnormal: the low bits of the mantissa are zero
        mantissa >>= -shift;
        shift = 0;
    }
    r.limbs.assign(static_cast<std::size_t>(shift / 32) + 3, 0);
    const unsigned bit = static_cast<unsigned>(shift % 32);
    const std::size_t limb = static_cast<std::size_t>(shift / 32);
    // mantissa * 2^bit spread over three limbs (mantissa < 2^53, bit < 32).
    r.limbs[limb] = static_cast<std::uint32_t>(mantissa << bit);
    r.limbs[limb + 1] =
        static_cast<std::uint32_t>(bit == 0 ? mantissa >> 32 : mantissa >> (32 - bit));
    r.limbs[limb + 2] = static_cast<std::uint32_t>(bit == 0 ? 0 : mantissa >> (64 - bit));
    r.negative = x < 0;
    r.trim();
    return r;
}

template <int Dim>
std::array<BigInt, Dim> exact_difference(const Eigen::Matrix<double, Dim, 1>& b,
                                         const Eigen::Matrix<double, Dim, 1>& a) {
    std::array<BigInt, Dim> d;
    for (int i = 0; i < Dim; ++i) d[i] = subtract(scaled_integer(b[i]), scaled_integer(a[i]));
    return d;
}

int reference_orient3d(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
    const auto u = exact_difference<3>(b, a);
    const auto v = exact_difference<3>(c, a);
    const auto w = exact_difference<3>(d, a);
    const BigInt x = multiply(u[0], subtract(multiply(v[1], w[2]), multiply(v[2], w[1])));
    const BigInt y = multiply(u[1], subtract(multiply(v[2], w[0]), multiply(v[0], w[2])));
    const BigInt z = multiply(u[2], subtract(multiply(v[0], w[1]), multiply(v[1], w[0])));
    return add(add(x, y), z).sign();
}

int reference_orient2d(const Vector2d& a, const Vector2d& b, const Vector2d& c) {
    const auto u = exact_difference<2>(b, a);
    const auto v = exact_difference<2>(c, a);
    return subtract(multiply(u[0], v[1]), multiply(u[1], v[0])).sign();
}

int naive_orient3d(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d) {
    const double det = (b - a).cross(c - a).dot(d - a);
    return (det > 0) - (det < 0);
}

struct Counts {
    long cases = 0;
    long naive_wrong = 0;
};

// Checks orient3d on (a, b, c, d) and on the permutations whose sign is known
// from the first (odd permutations flip it).
void check_orient3d(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d,
                    Counts& counts) {
    const int expected = reference_orient3d(a, b, c, d);
    ++counts.cases;
    if (naive_orient3d(a, b, c, d) != expected) ++counts.naive_wrong;
    CHECK(orient3d(a, b, c, d) == expected);
    CHECK(orient3d(b, a, c, d) == -expected);
    CHECK(orient3d(d, b, c, a) == -expected);
    CHECK(orient3d(b, c, a, d) == expected);
    CHECK(PlaneSide(a, b, c).of(d) == expected);
    CHECK(PlaneSide(d, b, c).of(a) == -expected);
    // The filter alone names a side only when it is the exact one.
    const int certain = certain_common_side(a, b, c, d, d, d);
    CHECK(certain == 0 || certain == expected);
}

void check_orient2d(const Vector2d& a, const Vector2d& b, const Vector2d& c, Counts& counts) {
    const int expected = reference_orient2d(a, b, c);
    ++counts.cases;
    const double naive = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (((naive > 0) - (naive < 0)) != expected) ++counts.naive_wrong;
    CHECK(orient2d(a, b, c) == expected);
    CHECK(orient2d(b, a, c) == -expected);
    CHECK(orient2d(b, c, a) == expected);
}

void report(const char* what, const Counts& counts) {
    std::printf("  %-58s %6ld cases, double evaluation wrong in %ld\n", what, counts.cases,
                counts.naive_wrong);
}

Vector3d nudge(Vector3d x, int axis, int ulps) {
    for (int i = 0; i < std::abs(ulps); ++i) {
        x[axis] = std::nextafter(x[axis], ulps > 0 ? INFINITY : -INFINITY);
    }
    return x;
}

// Points on the plane z = x/2 + y/4 through the origin (up to the rounding
// of z), one coordinate moved by up to two ulps, around offsets 0, 1e8 and
// 1e15, at scales from 2^-700 to 2^600.
void near_coplanar(std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> ulps(-2, 2);
    std::uniform_int_distribution<int> axis(0, 2);
    const double offsets[] = {0.0, 1e8, 1e15};
    const int exponents[] = {-700, -332, 0, 332, 600};
    for (const double offset : offsets) {
        for (const int exponent : exponents) {
            Counts counts;
            for (int n = 0; n < 100; ++n) {
                std::array<Vector3d, 4> p;
                for (Vector3d& x : p) {
                    // Spread comparable to the offset: differences with all
                    // 53 bits, where double evaluation rounds.
                    const double spread = offset == 0.0 ? 1.0 : offset / 2;
                    x = {offset + spread * unit(random), offset + spread * unit(random), 0.0};
                    x.z() = x.x() / 2 + x.y() / 4;
                    x = {std::ldexp(x.x(), exponent), std::ldexp(x.y(), exponent),
                         std::ldexp(x.z(), exponent)};
                }
                p[3] = nudge(p[3], axis(random), ulps(random));
                check_orient3d(p[0], p[1], p[2], p[3], counts);
            }
            char what[96];
            std::snprintf(what, sizeof what, "orient3d near a plane, offset %g, scale 2^%d", offset,
                          exponent);
            report(what, counts);
        }
    }
}

// Exactly coplanar integer points (d = a + s(b - a) + t(c - a)), then one
// coordinate moved by one unit: the sign is decided by the last unit.
void integer_coplanar(std::mt19937_64& random) {
    std::uniform_int_distribution<std::int64_t> small(-1000, 1000);
    std::uniform_int_distribution<int> step(-1, 1);
    std::uniform_int_distribution<int> axis(0, 2);
    const double offsets[] = {0.0, 1e6, 1e8, 4503599627370496.0 /* 2^52 */};
    for (const double offset : offsets) {
        Counts counts;
        for (int n = 0; n < 200; ++n) {
            Eigen::Matrix<std::int64_t, 3, 1> a, b, c;
            for (int i = 0; i < 3; ++i) {
                a[i] = small(random);
                b[i] = small(random);
                c[i] = small(random);
            }
            const std::int64_t s = small(random) / 100, t = small(random) / 100;
            Eigen::Matrix<std::int64_t, 3, 1> d = a + s * (b - a) + t * (c - a);
            d[axis(random)] += step(random);
            const auto place = [offset](const Eigen::Matrix<std::int64_t, 3, 1>& x) {
                return Vector3d((x.cast<double>().array() + offset).matrix());
            };
            check_orient3d(place(a), place(b), place(c), place(d), counts);
        }
        char what[96];
        std::snprintf(what, sizeof what, "orient3d integer coplanar +-1, offset %g", offset);
        report(what, counts);
    }
}

// Random points whose coordinates mix magnitudes (within the exact range of
// docs/exact-predicates.md), most of them on a common plane.
void mixed_magnitudes(std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-300, 300);
    std::uniform_int_distribution<int> ulps(-1, 1);
    Counts counts;
    for (int n = 0; n < 600; ++n) {
        std::array<Vector3d, 4> p;
        const int base = exponent(random);
        for (Vector3d& x : p) {
            for (int i = 0; i < 2; ++i)
                x[i] = std::ldexp(unit(random), base + exponent(random) / 3);
            x.z() = x.x() / 2 + x.y() / 4;
        }
        for (Vector3d& x : p) x = nudge(x, 2, ulps(random));
        check_orient3d(p[0], p[1], p[2], p[3], counts);
    }
    report("orient3d mixed magnitudes 2^-400..2^400 near a plane", counts);
}

// Collinear points moved by one ulp (the classic failure of orient2d), and
// random integer points at offsets, compared with the reference.
void orient2d_cases(std::mt19937_64& random) {
    Counts near_line;
    for (int i = 0; i < 32; ++i) {
        for (int j = 0; j < 32; ++j) {
            const Vector2d a(0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53);
            check_orient2d(a, Vector2d(12, 12), Vector2d(24, 24), near_line);
        }
    }
    report("orient2d on a 32x32 ulp grid near the line y = x", near_line);
    Counts offsets;
    std::uniform_int_distribution<std::int64_t> small(-100, 100);
    for (const double offset : {0.0, 1e8, 1e15}) {
        for (int n = 0; n < 500; ++n) {
            const double ax = double(small(random)), ay = double(small(random));
            const double bx = double(small(random)), by = double(small(random));
            const double t = double(small(random) / 10);
            Vector2d a(ax + offset, ay + offset), b(bx + offset, by + offset);
            Vector2d c(ax + t * (bx - ax) + offset, ay + t * (by - ay) + offset);
            c.y() += double(small(random) % 2);
            check_orient2d(a, b, c, offsets);
        }
    }
    report("orient2d integer collinear +-1, offsets 0, 1e8, 1e15", offsets);
    Counts scales;
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const int exponent : {-1000, -664, 664, 1000}) {
        for (int n = 0; n < 150; ++n) {
            const Vector2d a(std::ldexp(unit(random), exponent),
                             std::ldexp(unit(random), exponent));
            const Vector2d b(std::ldexp(unit(random), exponent),
                             std::ldexp(unit(random), exponent));
            Vector2d c = a + (b - a) * 0.5;
            c.y() = std::nextafter(c.y(), n % 2 ? INFINITY : -INFINITY);
            check_orient2d(a, b, c, scales);
        }
    }
    report("orient2d near-collinear at scales 2^-1000..2^1000", scales);
}

// Degenerate and extreme inputs: coincident points, zeros, subnormals, the
// largest doubles (differences beyond the double range).
void edge_cases() {
    const Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    CHECK(orient3d(o, x, y, z) == 1);
    CHECK(orient3d(o, y, x, z) == -1);
    CHECK(orient3d(o, x, y, Vector3d(5, 7, 0)) == 0);
    CHECK(orient3d(o, o, y, z) == 0);
    const double tiny = 0x1p-1074;
    CHECK(orient3d(o, Vector3d(tiny, 0, 0), Vector3d(0, tiny, 0), Vector3d(0, 0, tiny)) == 1);
    CHECK(orient3d(o, Vector3d(tiny, 0, 0), Vector3d(0, tiny, 0), Vector3d(0, 0, -tiny)) == -1);
    const double huge = 0x1.fffffffffffffp1023;
    const Vector3d h(-huge, -huge, -huge);
    CHECK(orient3d(h, Vector3d(huge, -huge, -huge), Vector3d(-huge, huge, -huge),
                   Vector3d(-huge, -huge, huge)) == 1);
    CHECK(orient3d(h, Vector3d(huge, -huge, -huge), Vector3d(-huge, huge, -huge),
                   Vector3d(huge, huge, -huge)) == 0);
    CHECK(orient2d(Vector2d(-huge, -huge), Vector2d(huge, -huge), Vector2d(-huge, huge)) == 1);
    CHECK(orient2d(Vector2d(tiny, 0), Vector2d(0, tiny), Vector2d(0, 0)) == 1);
    // Not finite: outside the contract, but it must return (0), not loop.
    const Vector3d nan(NAN, 0, 0);
    CHECK(orient3d(nan, x, y, z) == 0);
    CHECK(orient2d(Vector2d(INFINITY, 0), Vector2d(0, 1), Vector2d(1, 0)) == 0);
    std::printf("  %-58s %6d cases\n", "zeros, subnormals, the largest doubles, not finite", 12);
}

// certain_common_side against the exact signs, for planes of unit size at
// offsets up to 1e8 and three points each well off the plane (half a unit),
// barely off (a millionth of a unit), exactly on it (a corner of the plane's
// triangle), or a corner moved by one ulp (on either side, or still on it):
// it names a side only when all three lie exactly on it, and it names it
// whenever all three are well off on one side (else it filters nothing).
void certain_common_sides(std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> kind_of(0, 3), axis_of(0, 2), ulps(-1, 1);
    std::bernoulli_distribution above(0.5);
    long cases = 0, named = 0, must_name = 0;
    for (const double offset : {0.0, 1e6, 1e8}) {
        for (int n = 0; n < 3000; ++n) {
            const Vector3d origin = Vector3d::Constant(offset);
            const Vector3d a = origin + Vector3d(unit(random), unit(random), unit(random));
            const Vector3d b = origin + Vector3d(unit(random), unit(random), unit(random));
            const Vector3d c = origin + Vector3d(unit(random), unit(random), unit(random));
            const Vector3d normal = (b - a).cross(c - a).normalized();
            if (!(normal.array().isFinite().all())) continue;
            // All three far off on one side in some cases, mixed in others.
            const bool one_side = n % 2 == 0, upward = above(random);
            std::array<Vector3d, 3> d;
            bool all_well_off = true;
            for (Vector3d& x : d) {
                const int kind = one_side ? 0 : kind_of(random);
                const Vector3d in_plane = a + unit(random) * (b - a) + unit(random) * (c - a);
                const double sign = (one_side ? upward : above(random)) ? 1.0 : -1.0;
                if (kind == 0) x = in_plane + 0.5 * sign * normal;
                if (kind == 1) x = in_plane + 1e-6 * sign * normal;
                if (kind == 2) x = (n % 3 == 0 ? a : n % 3 == 1 ? b : c);
                if (kind == 3) x = nudge(n % 3 == 0 ? a : c, axis_of(random), ulps(random));
                all_well_off &= kind == 0;
            }
            const int exact[3] = {reference_orient3d(a, b, c, d[0]),
                                  reference_orient3d(a, b, c, d[1]),
                                  reference_orient3d(a, b, c, d[2])};
            const int side = certain_common_side(a, b, c, d[0], d[1], d[2]);
            CHECK(side == 0 || (exact[0] == side && exact[1] == side && exact[2] == side));
            if (all_well_off && exact[0] == exact[1] && exact[1] == exact[2]) {
                ++must_name;
                CHECK(side == exact[0]);
            }
            ++cases;
            named += side != 0;
        }
    }
    CHECK(must_name > 1000);
    std::printf("  %-58s %6ld cases, %ld named a side (%ld had to)\n",
                "certain_common_side: three points, offsets to 1e8", cases, named, must_name);
}

// Random points with small integer coordinates: many exact zeros.
void random_small_integers(std::mt19937_64& random) {
    std::uniform_int_distribution<int> coordinate(-3, 3);
    Counts counts;
    for (int n = 0; n < 1500; ++n) {
        std::array<Vector3d, 4> p;
        for (Vector3d& x : p)
            x = Vector3d(coordinate(random), coordinate(random), coordinate(random));
        check_orient3d(p[0], p[1], p[2], p[3], counts);
        check_orient2d(p[0].head<2>(), p[1].head<2>(), p[2].head<2>(), counts);
    }
    report("orient3d and orient2d on random integers in [-3, 3]", counts);
}

// Points on coarse grids (integers times 2^k), where the exact evaluation
// computes the determinant of the integers in double when each difference
// fits in 16 bits (orient2d: 24) of the largest one's magnitude: coplanar
// (collinear) and one grid step off, with differences just inside and just
// past those widths, and some points off the grid by half a step.
void coarse_grids(std::mt19937_64& random) {
    Counts counts;
    for (const int k : {-300, -40, 0, 40, 250}) {
        for (const std::int64_t reach : {std::int64_t{1} << 14, std::int64_t{1} << 23}) {
            std::uniform_int_distribution<std::int64_t> coordinate(-reach, reach);
            std::uniform_int_distribution<int> step(-1, 1), axis(0, 2), coin(0, 3);
            for (int n = 0; n < 200; ++n) {
                Eigen::Matrix<std::int64_t, 3, 1> a, b, c;
                for (int i = 0; i < 3; ++i) {
                    a[i] = coordinate(random);
                    b[i] = coordinate(random);
                    c[i] = a[i] + (b[i] - a[i]) / 2 + step(random);
                }
                Eigen::Matrix<std::int64_t, 3, 1> d = a + (b - a) - (c - a);
                d[axis(random)] += step(random);
                const double off_grid = coin(random) == 0 ? 0.5 : 0.0;
                auto place = [k](const Eigen::Matrix<std::int64_t, 3, 1>& x, double shift) {
                    return Vector3d(std::ldexp(double(x[0]) + shift, k),
                                    std::ldexp(double(x[1]), k), std::ldexp(double(x[2]), k));
                };
                check_orient3d(place(a, 0), place(b, 0), place(c, 0), place(d, off_grid), counts);
                check_orient2d(place(a, 0).head<2>(), place(b, 0).head<2>(),
                               place(d, off_grid).head<2>(), counts);
            }
        }
    }
    report("orient3d and orient2d on coarse grids, 2^-300 to 2^250", counts);
}

// Points sharing coordinates, as the corners of parts resting on each other
// in a CAD or voxel assembly do (a far offset, the steps not on a coarse
// grid): determinants zero because factors are, and near them, one
// coordinate moved by an ulp, determinants that are not.
void shared_coordinates(std::mt19937_64& random) {
    std::uniform_int_distribution<int> pick(0, 2), ulps(-1, 1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Counts counts;
    for (const double offset : {0.0, 1e6, 1e15}) {
        // Three values per axis, one of them irrational-looking.
        std::array<std::array<double, 3>, 3> values;
        for (auto& axis : values) axis = {offset, offset + 1.0, offset + 0.3 + 0.1 * unit(random)};
        for (int n = 0; n < 400; ++n) {
            std::array<Vector3d, 4> p;
            for (Vector3d& x : p)
                for (int i = 0; i < 3; ++i) x[i] = values[i][pick(random)];
            if (n % 2) p[3] = nudge(p[3], pick(random), ulps(random));
            check_orient3d(p[0], p[1], p[2], p[3], counts);
            check_orient2d(p[0].head<2>(), p[1].head<2>(), p[3].head<2>(), counts);
        }
    }
    report("orient3d and orient2d on shared coordinates, offsets to 1e15", counts);
}

}  // namespace

int main() {
    std::mt19937_64 random(20261124);
    std::printf("exact predicates against an exact integer reference:\n");
    edge_cases();
    near_coplanar(random);
    integer_coplanar(random);
    mixed_magnitudes(random);
    orient2d_cases(random);
    random_small_integers(random);
    coarse_grids(random);
    shared_coordinates(random);
    certain_common_sides(random);
    return polymass_test::finish("test_exact_predicates");
}
