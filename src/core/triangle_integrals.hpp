// Closed-form sums of a triangle, in two forms (docs/integrals.md, section 3):
//
// - flux: the face sums of the divergence theorem (the δ, f, g
//   sub-expressions). Parameterising the triangle P0 + u E1 + v E2 makes
//   n dS = δ du dv with δ = E1 × E2, and the face integrals collapse to
//   polynomials in the vertex coordinates (with the x²y term in full). A
//   face's sums are those of the polygon path, so meshes mixing triangles and
//   polygons take this form.
// - cone: the integrals over the signed tetrahedron from the reference point
//   to the triangle, a third fewer operations. Over a closed surface the
//   two forms give the same totals (not face by face), so a mesh of triangles
//   only takes this one.
//
// Both are the fast path: no normalisation, no projection, no division per
// triangle.
//
// T is double or a vector of doubles (lanes.hpp): the same expressions then
// integrate several triangles at once.
#pragma once

#include "lanes.hpp"
#include "volume_integrals.hpp"

namespace polymass::core {

enum class TriangleForm { flux, cone };

// The sums of triangles (FaceSums, or the same volume integrals from cones),
// each times a constant (6 for x, 12 for the squares, 20 for the flux form's
// cubes and 40 for the cone form's, 60 for the mixed terms) that scaled()
// divides out once per batch instead of once per triangle. Summed lane by
// lane in the triangles' order: the same sums, in the same order, whatever
// the instruction set.
template <class T>
struct UnscaledTriangleSums {
    T x{};
    T squares[3]{};
    T cubes[3]{};
    T mixed[3]{};  // x²y, y²z, z²x (flux); xy, yz, zx (cone)
};

template <TriangleForm form>
inline FaceSums scaled(const UnscaledTriangleSums<double>& unscaled) {
    constexpr double cubes_divisor = form == TriangleForm::cone ? 40.0 : 20.0;
    FaceSums sums;
    sums.x = unscaled.x / 6.0;
    for (int axis = 0; axis < 3; ++axis) {
        sums.squares[axis] = unscaled.squares[axis] / 12.0;
        sums.cubes[axis] = unscaled.cubes[axis] / cubes_divisor;
        sums.mixed[axis] = unscaled.mixed[axis] / 60.0;
    }
    return sums;
}

namespace detail {

// f1, f2, f3 and g0, g1, g2 of one coordinate w at the three vertices:
//   f1 = w0 + w1 + w2, fn = sn(w0, w1) + w2 f(n-1), gi = f2 + wi f1 + wi².
template <class T>
struct TriangleCoordinateTerms {
    T f1, f2, f3;
    T g[3];

    __attribute__((always_inline)) explicit TriangleCoordinateTerms(const T (&w)[3]) {
        const T s1 = w[0] + w[1];
        const T w0w0 = w[0] * w[0];
        const T s2 = w0w0 + w[1] * s1;  // w0² + w0 w1 + w1²
        f1 = s1 + w[2];
        f2 = s2 + w[2] * f1;
        f3 = w[0] * w0w0 + w[1] * s2 + w[2] * f2;  // s3 + w2 f2
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) g[i] = f2 + w[i] * (f1 + w[i]);
    }
};

}  // namespace detail

// The edges E1 = p1 − p0, E2 = p2 − p0 of a triangle (per lane) with vertex
// coordinates p[axis][vertex], and δ = E1 × E2, whose length is twice the area.
template <class T>
struct TriangleEdges {
    T e1[3], e2[3], delta[3];

    __attribute__((always_inline)) explicit TriangleEdges(const T (&p)[3][3]) {
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) {
            e1[axis] = p[axis][1] - p[axis][0];
            e2[axis] = p[axis][2] - p[axis][0];
        }
        delta[0] = e1[1] * e2[2] - e1[2] * e2[1];
        delta[1] = e1[2] * e2[0] - e1[0] * e2[2];
        delta[2] = e1[0] * e2[1] - e1[1] * e2[0];
    }
};

// Adds the unscaled sums of triangles with vertex coordinates p[axis][vertex]
// and δ from TriangleEdges (a lane whose δ is zero adds zeros) to the running
// sums, whose lanes take the triangles' terms from lane group first_group on
// (T is Lanes or WideLanes; `groups` of its lane groups are added). Each sum
// is added to as soon as its term is known, which keeps fewer values alive at
// once; the order of the additions into any one sum is the same.
template <TriangleForm form, class T>
__attribute__((always_inline)) inline void add_unscaled_triangle_sums(
    UnscaledTriangleSums<WideLanes>& sums, const T (&p)[3][3], const T (&delta)[3], int first_group,
    int groups) {
    auto add = [first_group, groups](WideLanes& sum, const T& term) {
        add_lane_groups(sum, term, first_group, groups);
    };
    if constexpr (form == TriangleForm::cone) {
        // d = p0 · δ = p0 · (p1 × p2): six times the tetrahedron's signed
        // volume. With the pair sums q_k = p_k + p_(k+1) and s = p0 + p1 + p2,
        // ∫ x_i x_j = d/120 · (Σ_k p_k,i p_k,j + s_i s_j) = d/120 · Σ_k q_k,i q_k,j.
        const T d = p[0][0] * delta[0] + p[1][0] * delta[1] + p[2][0] * delta[2];
        T q[3][3];
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) {
            q[axis][0] = p[axis][0] + p[axis][1];
            q[axis][1] = p[axis][1] + p[axis][2];
            q[axis][2] = p[axis][2] + p[axis][0];
        }
        add(sums.x, d);
#pragma GCC unroll 3
        for (int axis = 0; axis < 3; ++axis) {
            const int next = (axis + 1) % 3;
            add(sums.squares[axis], d * (q[axis][0] + p[axis][2]));
            add(sums.cubes[axis],
                d * (q[axis][0] * q[axis][0] + q[axis][1] * q[axis][1] + q[axis][2] * q[axis][2]));
            add(sums.mixed[axis],
                d * (q[axis][0] * q[next][0] + q[axis][1] * q[next][1] + q[axis][2] * q[next][2]));
        }
        return;
    }
#pragma GCC unroll 3
    for (int axis = 0; axis < 3; ++axis) {
        // The mixed term of axis a is ∫a²b with b the next axis (x²y, y²z, z²x).
        const int next = (axis + 1) % 3;
        const detail::TriangleCoordinateTerms<T> t(p[axis]);
        if (axis == 0) add(sums.x, delta[0] * t.f1);
        add(sums.squares[axis], delta[axis] * t.f2);
        add(sums.cubes[axis], delta[axis] * t.f3);
        add(sums.mixed[axis],
            delta[axis] * (p[next][0] * t.g[0] + p[next][1] * t.g[1] + p[next][2] * t.g[2]));
    }
}

}  // namespace polymass::core
