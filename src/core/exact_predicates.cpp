// Orientation predicates: a floating-point filter, and an exact evaluation
// with floating-point expansions when the filter cannot decide. Derivations:
// docs/exact-predicates.md.
#include "core/exact_predicates.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace polymass::core {
namespace {

// Unit roundoff of double (round to nearest): |fl(x op y) - x op y| <= epsilon |x op y|.
constexpr double epsilon = 0x1p-53;

// Covers the absolute error of products that fall into the subnormal range
// (at most 2^-1075 each): 2^15 of them, far more than any filter makes.
constexpr double underflow_cover = 0x1p-1060;

// Filter constants: the relative error bounds of docs/exact-predicates.md
// (8 and 4 roundings in a monomial), rounded up to leave room for the
// rounding of the permanent and of the bound itself.
constexpr double orient3d_relative_bound = 9 * epsilon;
constexpr double orient2d_relative_bound = 5 * epsilon;

// Whether the filter decides: |det| above the bound `relative +
// underflow_cover * scale`, rounded as that expression is
// (docs/exact-predicates.md). Arithmetic with subnormal results stalls the
// processor (a microcode assist of about a hundred cycles), and computed on
// every call the cover was most of the cost of the intersection check; so:
// - a relative part of at least 2^-900 has an ulp of at least 2^-952, and a
//   cover of at most 2^-960 (scale up to 2^100) is below half of it: the
//   rounded bound is the relative part itself;
// - a relative part below that with a cover below 2^-1020 (scale below
//   2^40) is a permanent at the foot of the double range, most often exactly
//   zero (a point on an axis-aligned plane): the filter does not decide, and
//   the exact evaluation does;
// - otherwise the bound is computed as it reads, without subnormal results.
inline bool filter_decides(double det, double relative, double scale) {
    const bool relative_normal = relative >= 0x1p-900;
    if (relative_normal && scale <= 0x1p100) return std::fabs(det) > relative;
    if (!relative_normal && scale < 0x1p40) return false;
    return std::fabs(det) > relative + underflow_cover * scale;
}

// Whether x y - z w is zero by its factors alone: each product has a factor
// that is exactly zero. The factors are rounded differences, and a
// difference of finite doubles rounds to zero only when it is zero (the
// operands are equal), so this is exact, and as cheap as the filter. Points
// on a common axis-aligned plane (or, in a plane, line) make a determinant
// zero this way: faces of parts resting on each other in CAD and voxel
// assemblies, where the filter always declines (docs/exact-predicates.md).
inline bool zero_by_factors(double x, double y, double z, double w) {
    return (x == 0.0 || y == 0.0) && (z == 0.0 || w == 0.0);
}

// Whether det[u, v, w] = sum over k of (u x v)_k w_k is zero by its factors:
// each w_k is zero, or the component (u x v)_k is by its factors.
inline bool determinant_zero_by_factors(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                        const Eigen::Vector3d& w) {
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        if (!(w[k] == 0.0 || zero_by_factors(u[i], v[j], u[j], v[i]))) return false;
    }
    return true;
}

// A value held exactly as hi + lo with |lo| <= ulp(hi) / 2.
struct TwoTerm {
    double hi;
    double lo;
};

// Exact sum (Knuth): a + b == hi + lo whenever a + b does not overflow.
inline TwoTerm two_sum(double a, double b) {
    const double sum = a + b;
    const double b_part = sum - a;
    const double a_part = sum - b_part;
    return {sum, (a - a_part) + (b - b_part)};
}

// Exact product: a * b == hi + lo whenever the rounding error of a * b is
// representable (no overflow, and the product's last bit not below 2^-1074).
inline TwoTerm two_product(double a, double b) {
    const double product = a * b;
    return {product, std::fma(a, b, -product)};
}

// A nonoverlapping expansion: the sum of its terms, stored in increasing
// magnitude with zeros removed, each term's lowest set bit above the highest
// set bit of the terms before it. Its sign is the sign of its last term.
template <std::size_t Capacity>
class Expansion {
public:
    // Adds b exactly (grow-expansion with zero elimination): carries b up
    // through the terms with two_sum, keeping every nonzero remainder.
    void add(double b) {
        assert(count_ < Capacity);
        if (b == 0.0) return;
        double carry = b;
        std::size_t kept = 0;
        for (std::size_t i = 0; i < count_; ++i) {
            const TwoTerm s = two_sum(carry, terms_[i]);
            carry = s.hi;
            if (s.lo != 0.0) terms_[kept++] = s.lo;
        }
        if (carry != 0.0) terms_[kept++] = carry;
        count_ = kept;
    }

    int sign() const {
        if (count_ == 0) return 0;
        return terms_[count_ - 1] > 0.0 ? 1 : -1;
    }

private:
    std::array<double, Capacity> terms_{};
    std::size_t count_ = 0;
};

// Adds sign * x * y exactly: four exact products of doubles. Zero parts (the
// low part of a difference that was exact in double, usually) are skipped.
template <std::size_t Capacity>
void add_product(Expansion<Capacity>& sum, double sign, const TwoTerm& x, const TwoTerm& y) {
    for (const double xi : {x.hi, x.lo}) {
        if (xi == 0.0) continue;
        for (const double yi : {y.hi, y.lo}) {
            if (yi == 0.0) continue;
            const TwoTerm p = two_product(xi, yi);
            sum.add(sign * p.hi);
            sum.add(sign * p.lo);
        }
    }
}

// Adds sign * x * y * z exactly: 8 products of three doubles, each split
// into 4 exact terms (the two parts of x_i y_j, each times z_k).
template <std::size_t Capacity>
void add_product(Expansion<Capacity>& sum, double sign, const TwoTerm& x, const TwoTerm& y,
                 const TwoTerm& z) {
    for (const double xi : {x.hi, x.lo}) {
        if (xi == 0.0) continue;
        for (const double yi : {y.hi, y.lo}) {
            if (yi == 0.0) continue;
            const TwoTerm p = two_product(xi, yi);
            for (const double zi : {z.hi, z.lo}) {
                if (zi == 0.0) continue;
                const TwoTerm hi = two_product(p.hi, zi);
                const TwoTerm lo = two_product(p.lo, zi);
                sum.add(sign * hi.hi);
                sum.add(sign * hi.lo);
                sum.add(sign * lo.hi);
                sum.add(sign * lo.lo);
            }
        }
    }
}

// One row of the determinant, b - a, as exact two-term components.
template <int Dim>
using Row = std::array<TwoTerm, Dim>;

// b - a exactly; false when a component overflows.
template <int Dim, class Vector>
bool exact_difference(const Vector& b, const Vector& a, Row<Dim>& row) {
    for (int i = 0; i < Dim; ++i) {
        row[i] = two_sum(b[i], -a[i]);
        if (!std::isfinite(row[i].hi)) return false;
    }
    return true;
}

// Multiplies the row by the power of two that brings its largest component
// to [2^top, 2^(top+1)): the determinant is linear in each row, so its sign
// does not change. False when the row is zero (then the determinant is zero).
template <int Dim>
bool normalize(Row<Dim>& row, int top) {
    double largest = 0.0;
    for (const TwoTerm& c : row) largest = std::fmax(largest, std::fabs(c.hi));
    if (largest == 0.0) return false;
    const int shift = top - std::ilogb(largest);
    for (TwoTerm& c : row) {
        c.hi = std::ldexp(c.hi, shift);
        c.lo = std::ldexp(c.lo, shift);
    }
    return true;
}

// Rows scaled to [2^336, 2^337): a product of three components is below
// 2^1011 and the 192 exact terms sum below 2^1019, so nothing overflows; the
// products' last bits stay above 2^-1074 within the range stated in
// docs/exact-predicates.md.
constexpr int orient3d_row_top = 336;
// 6 monomials x 8 products of three doubles x 4 exact terms.
constexpr std::size_t orient3d_terms = 6 * 8 * 4;

// Rows scaled to [2^508, 2^509): products below 2^1018, the 16 terms sum below 2^1022.
constexpr int orient2d_row_top = 508;
// 2 monomials x 4 products of two doubles x 2 exact terms.
constexpr std::size_t orient2d_terms = 2 * 4 * 2;
static_assert(2 * (orient2d_row_top + 1) + 4 <= 1023, "orient2d terms must not overflow");
static_assert(3 * (orient3d_row_top + 1) + 8 <= 1023, "orient3d terms must not overflow");

// Exact inputs on a coarse grid, the cheapest exact case: every difference
// exact in one double and a whole multiple of 2^e, with e `bits` below the
// largest one's exponent, so that each is an integer of at most `bits` bits
// times 2^e. Meshes from CAD, voxels or integer coordinates are made of such
// points, and their contacts are where predicates are exactly zero. Then the
// determinant of the integers is exact in double (orient3d: 16 bits, minors
// below 2^33, monomials below 2^49, their sum below 2^51; orient2d: 24 bits,
// products below 2^48), and its sign is the determinant's. The integers are
// the differences times 2^-e, a power of two: exact, for every difference in
// the range checked here. False when the rows are not of this kind.
template <int Dim>
bool on_coarse_grid(const std::array<Row<Dim>, Dim>& rows, int bits,
                    std::array<std::array<double, Dim>, Dim>& integers) {
    double largest = 0.0;
    for (const Row<Dim>& row : rows)
        for (const TwoTerm& c : row) {
            if (c.lo != 0.0) return false;
            largest = std::max(largest, std::fabs(c.hi));  // finite: no fmax call
        }
    if (!(largest >= 0x1p-300 && largest <= 0x1p300)) return false;
    // 2^-e from the exponent bits (ldexp is a library call).
    std::uint64_t largest_bits = 0;
    std::memcpy(&largest_bits, &largest, sizeof largest);
    const int e = int(largest_bits >> 52) - 1023 - (bits - 1);
    const std::uint64_t scale_bits = std::uint64_t(1023 - e) << 52;
    double scale = 0.0;
    std::memcpy(&scale, &scale_bits, sizeof scale);
    for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) {
            // Below 2^bits in magnitude: a conversion truncates it exactly.
            const double integer = rows[i][j].hi * scale;
            if (double(std::int64_t(integer)) != integer) return false;
            integers[i][j] = integer;
        }
    return true;
}

// The common exact case, cheaply: every difference exact in one double (float
// input, or coordinates within a factor of two of each other) and of a
// magnitude whose products of three neither overflow nor lose their low
// parts below 2^-1074. Then each 2x2 minor is an exact sum of two exact
// products (four terms) and the determinant the sum of three minors each
// times one double (24 terms): no scaling, a few hundred operations.
bool rows_are_plain_doubles(const std::array<Row<3>, 3>& rows) {
    for (const Row<3>& row : rows)
        for (const TwoTerm& c : row) {
            const double size = std::fabs(c.hi);
            if (c.lo != 0.0 || (size != 0.0 && !(size >= 0x1p-300 && size <= 0x1p300)))
                return false;
        }
    return true;
}

int orient3d_of_plain_rows(const std::array<Row<3>, 3>& rows) {
    const Row<3>& u = rows[0];
    const Row<3>& v = rows[1];
    const Row<3>& w = rows[2];
    Expansion<24> det;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        // u_i (v_j w_k - v_k w_j): the cofactor expansion along the first row.
        const TwoTerm plus = two_product(v[j].hi, w[k].hi);
        const TwoTerm minus = two_product(v[k].hi, w[j].hi);
        for (const double term : {plus.lo, -minus.lo, plus.hi, -minus.hi}) {
            const TwoTerm product = two_product(term, u[i].hi);
            det.add(product.lo);
            det.add(product.hi);
        }
    }
    return det.sign();
}

int orient3d_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d) {
    std::array<Row<3>, 3> rows;
    if (!exact_difference<3>(b, a, rows[0]) || !exact_difference<3>(c, a, rows[1]) ||
        !exact_difference<3>(d, a, rows[2])) {
        // A difference beyond the double range (a coordinate above 2^1023):
        // a quarter of every point, exact unless a coordinate is also below
        // 2^-1020 (see the range in docs/exact-predicates.md). Non-finite
        // input breaks the precondition: 0 rather than endless recursion.
        if (!(a.allFinite() && b.allFinite() && c.allFinite() && d.allFinite())) return 0;
        return orient3d_exact(a / 4, b / 4, c / 4, d / 4);
    }
    // Two of the points the same make the determinant zero: checked before
    // any scaling, as it is the common case here (a corner shared by two
    // triangles).
    if (a == b || a == c || a == d || b == c || b == d || c == d) return 0;
    if (std::array<std::array<double, 3>, 3> m; on_coarse_grid<3>(rows, 16, m)) {
        const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) +
                           m[0][1] * (m[1][2] * m[2][0] - m[1][0] * m[2][2]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        return (det > 0.0) - (det < 0.0);
    }
    if (rows_are_plain_doubles(rows)) return orient3d_of_plain_rows(rows);
    for (Row<3>& row : rows) normalize<3>(row, orient3d_row_top);
    const Row<3>& u = rows[0];
    const Row<3>& v = rows[1];
    const Row<3>& w = rows[2];
    Expansion<orient3d_terms> det;
    add_product(det, 1.0, u[0], v[1], w[2]);
    add_product(det, -1.0, u[0], v[2], w[1]);
    add_product(det, 1.0, u[1], v[2], w[0]);
    add_product(det, -1.0, u[1], v[0], w[2]);
    add_product(det, 1.0, u[2], v[0], w[1]);
    add_product(det, -1.0, u[2], v[1], w[0]);
    return det.sign();
}

int orient2d_exact(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    std::array<Row<2>, 2> rows;
    if (!exact_difference<2>(b, a, rows[0]) || !exact_difference<2>(c, a, rows[1])) {
        if (!(a.allFinite() && b.allFinite() && c.allFinite())) return 0;
        return orient2d_exact(a / 4, b / 4, c / 4);
    }
    if (std::array<std::array<double, 2>, 2> m; on_coarse_grid<2>(rows, 24, m)) {
        const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        return (det > 0.0) - (det < 0.0);
    }
    for (Row<2>& row : rows) {
        if (!normalize<2>(row, orient2d_row_top)) return 0;
    }
    Expansion<orient2d_terms> det;
    add_product(det, 1.0, rows[0][0], rows[1][1]);
    add_product(det, -1.0, rows[0][1], rows[1][0]);
    return det.sign();
}

}  // namespace

int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
    const double vy_wz = vy * wz, vz_wy = vz * wy;
    const double vz_wx = vz * wx, vx_wz = vx * wz;
    const double vx_wy = vx * wy, vy_wx = vy * wx;
    const double det = ux * (vy_wz - vz_wy) + uy * (vz_wx - vx_wz) + uz * (vx_wy - vy_wx);
    const double aux = std::fabs(ux), auy = std::fabs(uy), auz = std::fabs(uz);
    const double permanent = aux * (std::fabs(vy_wz) + std::fabs(vz_wy)) +
                             auy * (std::fabs(vz_wx) + std::fabs(vx_wz)) +
                             auz * (std::fabs(vx_wy) + std::fabs(vy_wx));
    // NaN or infinity anywhere (overflow) makes the comparison false.
    if (filter_decides(det, orient3d_relative_bound * permanent, aux + auy + auz + 1.0))
        return det > 0.0 ? 1 : -1;
    if (determinant_zero_by_factors({ux, uy, uz}, {vx, vy, vz}, {wx, wy, wz})) return 0;
    return orient3d_exact(a, b, c, d);
}

namespace {

__attribute__((always_inline)) inline PlaneNormal plane_normal(const Eigen::Vector3d& a,
                                                               const Eigen::Vector3d& b,
                                                               const Eigen::Vector3d& c) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double uy_vz = uy * vz, uz_vy = uz * vy;
    const double uz_vx = uz * vx, ux_vz = ux * vz;
    const double ux_vy = ux * vy, uy_vx = uy * vx;
    return {{uy_vz - uz_vy, uz_vx - ux_vz, ux_vy - uy_vx},
            {std::fabs(uy_vz) + std::fabs(uz_vy), std::fabs(uz_vx) + std::fabs(ux_vz),
             std::fabs(ux_vy) + std::fabs(uy_vx)}};
}

// The sign of orient3d(a, b, c, d) when the filter alone decides it, else 0:
// the same bound as orient3d's, the determinant expanded along d − a.
__attribute__((always_inline)) inline int filtered_side(const PlaneNormal& plane,
                                                        const Eigen::Vector3d& a,
                                                        const Eigen::Vector3d& d) {
    const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
    const double det = wx * plane.normal[0] + wy * plane.normal[1] + wz * plane.normal[2];
    const double awx = std::fabs(wx), awy = std::fabs(wy), awz = std::fabs(wz);
    const double permanent =
        awx * plane.permanent[0] + awy * plane.permanent[1] + awz * plane.permanent[2];
    // NaN or infinity anywhere (overflow) makes the comparison false.
    if (filter_decides(det, orient3d_relative_bound * permanent, awx + awy + awz + 1.0))
        return det > 0.0 ? 1 : -1;
    return 0;
}

}  // namespace

PlaneSide::PlaneSide(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
    : a_(a), b_(b), c_(c), plane_(plane_normal(a, b, c)) {}

int certain_common_side(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, const Eigen::Vector3d& d0,
                        const Eigen::Vector3d& d1, const Eigen::Vector3d& d2) {
    const PlaneNormal plane = plane_normal(a, b, c);
    const int side = filtered_side(plane, a, d0);
    return side != 0 && filtered_side(plane, a, d1) == side && filtered_side(plane, a, d2) == side
               ? side
               : 0;
}

int PlaneSide::of(const Eigen::Vector3d& d) const {
    if (const int side = filtered_side(plane_, a_, d); side != 0) return side;
    // The normal's factors found again rather than kept for every plane:
    // most planes never get here.
    if (determinant_zero_by_factors(b_ - a_, c_ - a_, d - a_)) return 0;
    return orient3d_exact(a_, b_, c_, d);
}

int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    const double ux_vy = ux * vy, uy_vx = uy * vx;
    const double det = ux_vy - uy_vx;
    if (filter_decides(det, orient2d_relative_bound * (std::fabs(ux_vy) + std::fabs(uy_vx)), 1.0))
        return det > 0.0 ? 1 : -1;
    if (zero_by_factors(ux, vy, uy, vx)) return 0;
    return orient2d_exact(a, b, c);
}

}  // namespace polymass::core
