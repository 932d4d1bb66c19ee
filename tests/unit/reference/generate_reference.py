#!/usr/bin/env python3
"""Exact reference mass properties for the libpolymass unit tests.

Writes tests/unit/reference/exact_reference.h (committed): for every solid its
vertices, faces and the expected volume, centre of mass, inertia tensor about
the centre of mass and about the origin, and surface area.

Independence from the library: the library uses Mirtich's method (divergence
theorem, face projections, Green's theorem on edges). Here every face is cut
into a signed fan of triangles and every triangle is joined to a reference
point into a signed tetrahedron, whose volume, first and second moments have
closed forms (Tonon 2004):

    V            = det(b - a, c - a, d - a) / 6
    int x_i dV   = V * (a_i + b_i + c_i + d_i) / 4
    int x_i x_j  = V / 20 * (sum_k v_k,i v_k,j + (sum_k v_k,i)(sum_k v_k,j))

evaluated in exact rational arithmetic (fractions.Fraction). A signed fan of a
planar polygon equals the polygon as a 2-chain, so this is exact for
non-convex faces as well. Surface area is |sum of triangle cross products| / 2
per face, a square root of a rational, evaluated with decimal at 60 digits.

Every coordinate is a dyadic rational small enough that a double holds it
exactly (checked), and every expected value is printed with 17 significant
digits of the exact rational, so the only rounding is the final one.

Usage:
    generate_reference.py            rewrite exact_reference.h beside this file
    generate_reference.py --check    exit 1 if exact_reference.h is not current
    generate_reference.py --output F write to F
"""

import argparse
import math
import sys
from decimal import Decimal, getcontext
from fractions import Fraction as F
from pathlib import Path

getcontext().prec = 60

HERE = Path(__file__).resolve().parent
DEFAULT_OUTPUT = HERE / "exact_reference.h"


# ---------------------------------------------------------------------------
# Exact helpers
# ---------------------------------------------------------------------------


def dyadic(x, bits):
    """x rounded to the grid 2^-bits, as an exact Fraction."""
    return F(round(x * (1 << bits)), 1 << bits)


def sub(a, b):
    return tuple(p - q for p, q in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def decimal_of(fr):
    return Decimal(fr.numerator) / Decimal(fr.denominator)


def c_double(fr):
    """The exact rational as a C double literal with 17 significant digits."""
    if fr == 0:
        return "0.0"
    text = format(decimal_of(fr), ".16e")
    mantissa, exponent = text.split("e")
    return "%se%+03d" % (mantissa, int(exponent))


def c_exact_double(fr):
    """A value a double holds exactly (coordinates): shortest round-trip form."""
    value = float(fr)
    if F(value) != fr:
        raise ValueError("%s is not exactly representable as a double" % fr)
    text = repr(value)
    if "e" not in text and "." not in text and "inf" not in text:
        text += ".0"
    return text


class Mesh:
    def __init__(self, name, comment):
        self.name = name
        self.comment = comment
        self.vertices = []
        self.faces = []
        # Faces whose area is not part of the reference (overlapping fans):
        # then the surface area is left NaN.
        self.area_known = True

    def vertex(self, x, y, z):
        self.vertices.append((F(x), F(y), F(z)))
        return len(self.vertices) - 1

    def face(self, *indices):
        assert len(indices) >= 3
        self.faces.append(tuple(indices))

    def append(self, other):
        base = len(self.vertices)
        self.vertices.extend(other.vertices)
        for f in other.faces:
            self.faces.append(tuple(base + i for i in f))

    def reversed_faces(self):
        self.faces = [tuple(reversed(f)) for f in self.faces]
        return self

    def all_triangles(self):
        return all(len(f) == 3 for f in self.faces)


# ---------------------------------------------------------------------------
# Integration: signed tetrahedra from a reference point
# ---------------------------------------------------------------------------


class Integrals:
    def __init__(self):
        self.volume = F(0)
        self.first = [F(0)] * 3
        self.second = [[F(0)] * 3 for _ in range(3)]

    def add_tetrahedron(self, a, b, c, d):
        v6 = dot(sub(b, a), cross(sub(c, a), sub(d, a)))
        v = v6 / 6
        if v == 0:
            return
        pts = (a, b, c, d)
        s = [sum(p[i] for p in pts) for i in range(3)]
        self.volume += v
        for i in range(3):
            self.first[i] += v * s[i] / 4
        for i in range(3):
            for j in range(3):
                q = sum(p[i] * p[j] for p in pts)
                self.second[i][j] += v / 20 * (q + s[i] * s[j])


def face_fan(mesh, face):
    """The signed fan of triangles of a face, from its first vertex."""
    p = [mesh.vertices[i] for i in face]
    return [(p[0], p[k], p[k + 1]) for k in range(1, len(p) - 1)]


def integrate(mesh, reference_point):
    acc = Integrals()
    for face in mesh.faces:
        for a, b, c in face_fan(mesh, face):
            acc.add_tetrahedron(reference_point, a, b, c)
    return acc


def face_area(mesh, face):
    """Exact squared double area of the face (|vector area * 2|^2)."""
    n = (F(0), F(0), F(0))
    for a, b, c in face_fan(mesh, face):
        t = cross(sub(b, a), sub(c, a))
        n = tuple(x + y for x, y in zip(n, t))
    return dot(n, n)


def surface_area(mesh):
    total = Decimal(0)
    for face in mesh.faces:
        sq = face_area(mesh, face)
        total += decimal_of(sq).sqrt() / 2
    return total


def check_closed_and_planar(mesh):
    """Every directed edge is matched by its reverse; polygon faces are planar."""
    directed = {}
    for face in mesh.faces:
        for k in range(len(face)):
            e = (face[k], face[(k + 1) % len(face)])
            directed[e] = directed.get(e, 0) + 1
    for (a, b), count in directed.items():
        assert directed.get((b, a), 0) == count, "%s: edge (%d, %d) unmatched" % (mesh.name, a, b)
    for face in mesh.faces:
        if len(face) > 3:
            p = [mesh.vertices[i] for i in face]
            n = (F(0), F(0), F(0))
            for a, b, c in face_fan(mesh, face):
                n = tuple(x + y for x, y in zip(n, cross(sub(b, a), sub(c, a))))
            for q in p:
                assert dot(n, sub(q, p[0])) == 0, "%s: face %s is not planar" % (mesh.name, face)


class Reference:
    def __init__(self, mesh):
        check_closed_and_planar(mesh)
        for v in mesh.vertices:
            for x in v:
                c_exact_double(x)
        lo = [min(v[i] for v in mesh.vertices) for i in range(3)]
        # Two different reference points must agree exactly: a check of the
        # closedness and of the arithmetic.
        a = integrate(mesh, tuple(lo))
        b = integrate(mesh, (F(0), F(0), F(0)))
        assert a.volume == b.volume and a.first == b.first and a.second == b.second, mesh.name
        assert a.volume > 0, mesh.name
        self.mesh = mesh
        self.volume = a.volume
        self.com = [a.first[i] / a.volume for i in range(3)]
        s = a.second
        trace = s[0][0] + s[1][1] + s[2][2]
        self.inertia_origin = [
            [(trace if i == j else 0) - s[i][j] for j in range(3)] for i in range(3)
        ]
        c = self.com
        sc = [[s[i][j] - a.volume * c[i] * c[j] for j in range(3)] for i in range(3)]
        trace_c = sc[0][0] + sc[1][1] + sc[2][2]
        self.inertia = [[(trace_c if i == j else 0) - sc[i][j] for j in range(3)] for i in range(3)]
        self.area = surface_area(mesh) if mesh.area_known else None


# ---------------------------------------------------------------------------
# Solids
# ---------------------------------------------------------------------------


def box_mesh(name, lo, hi, triangulate=False, comment=None):
    m = Mesh(
        name,
        comment or "box [%s] x [%s] x [%s]" % tuple("%s, %s" % (lo[i], hi[i]) for i in range(3)),
    )
    add_box(m, lo, hi, triangulate)
    return m


def add_box(m, lo, hi, triangulate=False):
    base = len(m.vertices)
    for k in range(8):
        m.vertex(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2])
    quads = [
        (0, 2, 3, 1),  # z = lo, normal -z
        (4, 5, 7, 6),  # z = hi, normal +z
        (0, 1, 5, 4),  # y = lo, normal -y
        (2, 6, 7, 3),  # y = hi, normal +y
        (0, 4, 6, 2),  # x = lo, normal -x
        (1, 3, 7, 5),
    ]  # x = hi, normal +x
    for n, q in enumerate(quads):
        q = tuple(base + i for i in q)
        if triangulate:
            # alternate the diagonal so both kinds of split are exercised
            if n % 2 == 0:
                m.face(q[0], q[1], q[2])
                m.face(q[0], q[2], q[3])
            else:
                m.face(q[1], q[2], q[3])
                m.face(q[1], q[3], q[0])
        else:
            m.face(*q)


def prism_mesh(name, comment, polygon, z0, z1, cap="polygon", cap_triangles=None, side="quads"):
    """Extrusion of a counter-clockwise polygon from z0 to z1.

    cap: "polygon" (one face per cap), "triangles" (cap_triangles, a correct
    triangulation given as index triples into polygon), "fan" (fan from vertex
    0: overlapping for a non-convex polygon), "mixed" (top polygon, bottom
    triangles). side: "quads", "triangles" or "mixed" (every other quad split).
    """
    m = Mesh(name, comment)
    n = len(polygon)
    bottom = [m.vertex(x, y, z0) for x, y in polygon]
    top = [m.vertex(x, y, z1) for x, y in polygon]
    fan = [(0, k, k + 1) for k in range(1, n - 1)]

    def cap_faces(kind, ring, flip):
        if kind == "polygon":
            idx = list(ring)
            m.face(*(reversed(idx) if flip else idx))
            return
        tris = cap_triangles if kind == "triangles" else fan
        for t in tris:
            tri = [ring[i] for i in t]
            m.face(*(reversed(tri) if flip else tri))

    top_kind = "polygon" if cap == "mixed" else cap
    bottom_kind = "triangles" if cap == "mixed" else cap
    cap_faces(bottom_kind, bottom, True)
    cap_faces(top_kind, top, False)
    for k in range(n):
        a, b = bottom[k], bottom[(k + 1) % n]
        c, d = top[(k + 1) % n], top[k]
        split = side == "triangles" or (side == "mixed" and k % 2 == 1)
        if split:
            m.face(a, b, c)
            m.face(a, c, d)
        else:
            m.face(a, b, c, d)
    return m


def regular_polygon(n, radius, center, bits, phase=0.0):
    return [
        (
            center[0] + dyadic(radius * math.cos(phase + 2 * math.pi * k / n), bits),
            center[1] + dyadic(radius * math.sin(phase + 2 * math.pi * k / n), bits),
        )
        for k in range(n)
    ]


def star_polygon(points, r_outer, r_inner, center, bits):
    out = []
    for k in range(2 * points):
        r = r_outer if k % 2 == 0 else r_inner
        t = math.pi / 2 + math.pi * k / points
        out.append(
            (center[0] + dyadic(r * math.cos(t), bits), center[1] + dyadic(r * math.sin(t), bits))
        )
    return out


def ear_clip(polygon):
    """A correct triangulation of a simple counter-clockwise polygon."""

    def area2(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    def inside(p, a, b, c):
        return area2(a, b, p) >= 0 and area2(b, c, p) >= 0 and area2(c, a, p) >= 0

    idx = list(range(len(polygon)))
    tris = []
    while len(idx) > 3:
        for k in range(len(idx)):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = polygon[i0], polygon[i1], polygon[i2]
            if area2(a, b, c) <= 0:
                continue
            if any(inside(polygon[j], a, b, c) for j in idx if j not in (i0, i1, i2)):
                continue
            tris.append((i0, i1, i2))
            idx.pop(k)
            break
        else:
            raise ValueError("ear clipping failed")
    tris.append(tuple(idx))
    return tris


def tetrahedron_mesh(name, comment, p):
    m = Mesh(name, comment)
    for v in p:
        m.vertex(*v)
    a, b, c, d = range(4)
    # orient every face away from the opposite vertex
    for f, opp in (((a, b, c), d), ((a, b, d), c), ((a, c, d), b), ((b, c, d), a)):
        pa, pb, pc = (m.vertices[i] for i in f)
        n = cross(sub(pb, pa), sub(pc, pa))
        if dot(n, sub(m.vertices[opp], pa)) > 0:
            f = (f[0], f[2], f[1])
        m.face(*f)
    return m


def house_mesh():
    m = Mesh(
        "house",
        "box [0, 2] x [0, 1] x [0, 1] with a gable roof, ridge at z = 1.5 along x: "
        "pentagon end walls, sloped quads",
    )
    v = [
        m.vertex(*p)
        for p in [
            (0, 0, 0),
            (2, 0, 0),
            (2, 1, 0),
            (0, 1, 0),  # 0..3 floor
            (0, 0, 1),
            (2, 0, 1),
            (2, 1, 1),
            (0, 1, 1),  # 4..7 eaves
            (0, F(1, 2), F(3, 2)),
            (2, F(1, 2), F(3, 2)),
        ]
    ]  # 8, 9 ridge
    m.face(v[0], v[3], v[2], v[1])  # floor, -z
    m.face(v[0], v[1], v[5], v[4])  # y = 0 wall
    m.face(v[2], v[3], v[7], v[6])  # y = 1 wall
    m.face(v[0], v[4], v[8], v[7], v[3])  # x = 0 gable (pentagon), -x
    m.face(v[1], v[2], v[6], v[9], v[5])  # x = 2 gable, +x
    m.face(v[4], v[5], v[9], v[8])  # roof, y < 1/2 side
    m.face(v[6], v[7], v[8], v[9])  # roof, y > 1/2 side
    return m


def square_ring_mesh():
    """A genus-1 frame: outer square minus an off-centre rectangular hole,
    extruded, as one closed surface of 16 quads (trapezoids on the caps)."""
    m = Mesh(
        "square_ring",
        "genus-1 frame of 16 quads: [-1.5, 1.5]^2 minus hole "
        "[-0.5, 1] x [-0.75, 0.5], z in [0, 0.5]",
    )
    outer = [(F(-3, 2), F(-3, 2)), (F(3, 2), F(-3, 2)), (F(3, 2), F(3, 2)), (F(-3, 2), F(3, 2))]
    inner = [(F(-1, 2), F(-3, 4)), (F(1), F(-3, 4)), (F(1), F(1, 2)), (F(-1, 2), F(1, 2))]
    z0, z1 = F(0), F(1, 2)
    ob = [m.vertex(x, y, z0) for x, y in outer]
    ot = [m.vertex(x, y, z1) for x, y in outer]
    ib = [m.vertex(x, y, z0) for x, y in inner]
    it = [m.vertex(x, y, z1) for x, y in inner]
    for k in range(4):
        j = (k + 1) % 4
        m.face(ot[k], ot[j], it[j], it[k])  # top trapezoid, +z
        m.face(ob[k], ib[k], ib[j], ob[j])  # bottom trapezoid, -z
        m.face(ob[k], ob[j], ot[j], ot[k])  # outer wall, outward
        m.face(ib[k], it[k], it[j], ib[j])  # inner wall, towards the hole
    return m


def ring_of_boxes_mesh():
    m = Mesh(
        "ring_of_boxes",
        "square ring of 4 boxes (4 shells, touching face to face): "
        "[-1.5, 1.5]^2 minus [-0.75, 0.75]^2, z in [0, 0.5]",
    )
    a, b = F(3, 2), F(3, 4)
    h = F(1, 2)
    add_box(m, (-a, -a, 0), (a, -b, h))
    add_box(m, (-a, b, 0), (a, a, h))
    add_box(m, (-a, -b, 0), (-b, b, h))
    add_box(m, (b, -b, 0), (a, b, h), triangulate=True)
    return m


def cube_with_cavity_mesh():
    m = Mesh(
        "cube_cavity",
        "cube [-1, 1]^3 + (0.25, 0.5, -0.125) with an off-centre box cavity "
        "[-0.5, 0.25] x [-0.25, 0.5] x [0, 0.75] (inner shell reversed, triangulated)",
    )
    o = (F(1, 4), F(1, 2), F(-1, 8))
    add_box(m, tuple(-1 + o[i] for i in range(3)), tuple(1 + o[i] for i in range(3)))
    inner = Mesh("inner", "")
    add_box(
        inner,
        (F(-1, 2) + o[0], F(-1, 4) + o[1], 0 + o[2]),
        (F(1, 4) + o[0], F(1, 2) + o[1], F(3, 4) + o[2]),
        triangulate=True,
    )
    inner.reversed_faces()
    m.append(inner)
    return m


def torus_mesh(n_around, n_section, big_r, small_r, bits):
    m = Mesh(
        "torus_tris",
        "triangulated polygonal torus: %d x %d segments, R = %s, r = %s, "
        "coordinates rounded to 2^-%d" % (n_around, n_section, big_r, small_r, bits),
    )
    idx = {}
    for i in range(n_around):
        t = 2 * math.pi * i / n_around
        for j in range(n_section):
            p = 2 * math.pi * j / n_section
            rr = big_r + small_r * math.cos(p)
            idx[i, j] = m.vertex(
                dyadic(rr * math.cos(t), bits),
                dyadic(rr * math.sin(t), bits),
                dyadic(small_r * math.sin(p), bits),
            )
    for i in range(n_around):
        for j in range(n_section):
            a = idx[i, j]
            b = idx[(i + 1) % n_around, j]
            c = idx[(i + 1) % n_around, (j + 1) % n_section]
            d = idx[i, (j + 1) % n_section]
            m.face(a, b, c)
            m.face(a, c, d)
    return m


def octahedron_mesh():
    m = Mesh("octahedron_irregular", "irregular convex octahedron with dyadic vertices")
    px = m.vertex(F(5, 4), F(1, 8), F(-1, 16))
    nx = m.vertex(F(-3, 4), F(-1, 4), F(1, 8))
    py = m.vertex(F(1, 16), F(3, 2), F(1, 4))
    ny = m.vertex(F(-1, 8), F(-5, 4), F(-1, 8))
    pz = m.vertex(F(1, 4), F(-1, 16), F(7, 4))
    nz = m.vertex(F(-1, 16), F(1, 8), F(-1))
    for a, b in ((px, py), (py, nx), (nx, ny), (ny, px)):
        m.face(a, b, pz)
        m.face(b, a, nz)
    return m


def build_solids():
    solids = []
    q = F(1, 4)
    lo = (q, F(-1, 2), F(3, 4))
    hi = (q + F(3, 2), F(-1, 2) + F(3, 2), F(3, 4) + F(3, 2))
    solids.append(
        box_mesh("cube_quads", lo, hi, comment="cube of side 1.5 at (0.25, -0.5, 0.75), quads")
    )
    solids.append(
        box_mesh("cube_tris", lo, hi, triangulate=True, comment="the same cube, 12 triangles")
    )
    solids.append(
        box_mesh(
            "box",
            (-1, F(1, 2), 2),
            (2, 2, F(21, 8)),
            comment="box 3 x 1.5 x 0.625 at (-1, 0.5, 2), quads",
        )
    )
    o = (F(1, 2), F(1, 4), F(-1, 8))
    solids.append(
        tetrahedron_mesh(
            "tetra_corner",
            "corner tetrahedron, legs 2, 1.5, 0.75 along x, y, z from (0.5, 0.25, -0.125)",
            [o, (o[0] + 2, o[1], o[2]), (o[0], o[1] + F(3, 2), o[2]), (o[0], o[1], o[2] + F(3, 4))],
        )
    )
    s, o = F(3, 4), (F(1, 2), F(-1, 4), F(1, 8))
    solids.append(
        tetrahedron_mesh(
            "tetra_regular",
            "regular tetrahedron 0.75 * (+-1, +-1, +-1) (even sign count) + "
            "(0.5, -0.25, 0.125), edge 1.5 sqrt(2)",
            [
                tuple(o[i] + s * c[i] for i in range(3))
                for c in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1))
            ],
        )
    )
    solids.append(
        tetrahedron_mesh(
            "tetra_irregular",
            "irregular tetrahedron with dyadic vertices",
            [
                (F(-3, 8), F(1, 16), F(5, 32)),
                (F(9, 4), F(-1, 2), F(3, 8)),
                (F(1, 2), F(13, 8), F(-1, 4)),
                (F(3, 16), F(5, 16), F(15, 8)),
            ],
        )
    )
    tri = [(F(0), F(0)), (F(3, 2), F(1, 4)), (F(3, 8), F(5, 4))]
    solids.append(
        prism_mesh("prism_tri", "triangular prism, z in [-0.5, 1.25]", tri, F(-1, 2), F(5, 4))
    )
    hexagon = regular_polygon(6, 1.0, (F(1, 4), F(-1, 8)), 10)
    solids.append(
        prism_mesh(
            "prism_hex",
            "hexagonal prism (radius 1 rounded to 2^-10), z in [0, 0.75], hexagon caps",
            hexagon,
            F(0),
            F(3, 4),
        )
    )
    solids.append(
        prism_mesh(
            "prism_hex_mixed",
            "the hexagonal prism with a hexagon top cap, a "
            "triangulated bottom cap and every other side quad split",
            hexagon,
            F(0),
            F(3, 4),
            cap="mixed",
            cap_triangles=ear_clip(hexagon),
            side="mixed",
        )
    )
    dodecagon = regular_polygon(12, 1.25, (F(1, 2), F(1, 4)), 12, phase=0.1)
    solids.append(
        prism_mesh(
            "prism_12gon",
            "12-gon prism (radius 1.25 rounded to 2^-12), z in [-0.25, 0.5]",
            dodecagon,
            F(-1, 4),
            F(1, 2),
        )
    )
    ell = [
        (F(0), F(0)),
        (F(2), F(0)),
        (F(2), F(1, 2)),
        (F(1, 2), F(1, 2)),
        (F(1, 2), F(3, 2)),
        (F(0), F(3, 2)),
    ]
    ell = [(x + F(-3, 4), y + F(1, 8)) for x, y in ell]
    solids.append(
        prism_mesh(
            "prism_L",
            "L-shaped extrusion (non-convex hexagon caps), z in [0.25, 1]",
            ell,
            F(1, 4),
            F(1),
        )
    )
    star = star_polygon(5, 1.0, 0.375, (F(1, 8), F(-1, 4)), 10)
    solids.append(
        prism_mesh(
            "prism_star",
            "5-pointed star extrusion: caps are single non-convex 10-gons, z in [-0.5, 0.25]",
            star,
            F(-1, 2),
            F(1, 4),
        )
    )
    solids.append(
        prism_mesh(
            "prism_star_tris",
            "the star extrusion with correctly triangulated caps (ear clipping)",
            star,
            F(-1, 2),
            F(1, 4),
            cap="triangles",
            cap_triangles=ear_clip(star),
        )
    )
    fan = prism_mesh(
        "prism_star_fan",
        "the star extrusion with caps fanned from vertex 0 "
        "(overlapping, some inverted, triangles: a valid 2-chain, so volume "
        "and inertia are the same; surface area is not)",
        star,
        F(-1, 2),
        F(1, 4),
        cap="fan",
    )
    fan.area_known = False
    solids.append(fan)
    solids.append(house_mesh())
    solids.append(octahedron_mesh())
    solids.append(cube_with_cavity_mesh())
    solids.append(square_ring_mesh())
    solids.append(ring_of_boxes_mesh())
    solids.append(torus_mesh(16, 8, 2.0, 0.625, 12))
    return solids


# ---------------------------------------------------------------------------
# Self-checks against closed forms
# ---------------------------------------------------------------------------


def self_check(refs):
    by_name = {r.mesh.name: r for r in refs}
    # box: V = abc, Ixx = m (b^2 + c^2) / 12, products zero
    r = by_name["box"]
    a, b, c = F(3), F(3, 2), F(5, 8)
    v = a * b * c
    assert r.volume == v
    assert r.com == [F(1, 2), F(5, 4), F(37, 16)]
    assert r.inertia == [
        [v * (b * b + c * c) / 12, 0, 0],
        [0, v * (a * a + c * c) / 12, 0],
        [0, 0, v * (a * a + b * b) / 12],
    ]
    assert r.area == decimal_of(2 * (a * b + b * c + c * a))
    # a quad cube and a triangle cube are the same solid
    q, t = by_name["cube_quads"], by_name["cube_tris"]
    assert (q.volume, q.com, q.inertia, q.area) == (t.volume, t.com, t.inertia, t.area)
    # regular tetrahedron of edge e: V = e^3 / (6 sqrt 2), I = m e^2 / 20 * Identity
    r = by_name["tetra_regular"]
    e2 = F(9, 2)  # (1.5 sqrt 2)^2
    assert r.volume == F(9, 8)  # e^3 / (6 sqrt 2) with e = 1.5 sqrt 2: a third of the 1.5 cube
    assert r.inertia == [[r.volume * e2 / 20 if i == j else 0 for j in range(3)] for i in range(3)]
    # corner tetrahedron: V = abc/6, centroid at the mean of the vertices
    r = by_name["tetra_corner"]
    assert r.volume == F(2) * F(3, 2) * F(3, 4) / 6
    # the polygon, triangulated and fanned stars are the same solid
    p, t, f = by_name["prism_star"], by_name["prism_star_tris"], by_name["prism_star_fan"]
    assert (
        (p.volume, p.com, p.inertia) == (t.volume, t.com, t.inertia) == (f.volume, f.com, f.inertia)
    )
    assert p.area == t.area
    h, hm = by_name["prism_hex"], by_name["prism_hex_mixed"]
    assert (h.volume, h.com, h.inertia, h.area) == (hm.volume, hm.com, hm.inertia, hm.area)
    # a cube minus a cavity
    r = by_name["cube_cavity"]
    assert r.volume == 8 - F(3, 4) * F(3, 4) * F(3, 4)
    # the one-surface ring and the four boxes with a centred hole agree on volume
    r = by_name["ring_of_boxes"]
    assert r.volume == (9 - F(9, 4)) * F(1, 2)
    assert r.com[0] == 0 and r.com[1] == 0


# ---------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------


def format_list(items, per_line, indent="    "):
    lines = []
    for k in range(0, len(items), per_line):
        lines.append(indent + ", ".join(items[k : k + per_line]) + ",")
    return "\n".join(lines)


def render(refs):
    out = []
    w = out.append
    w("/* Generated by tests/unit/reference/generate_reference.py: DO NOT EDIT.")
    w(" *")
    w(" * Exact mass properties (unit density) of closed solids with dyadic")
    w(" * coordinates, from an exact rational decomposition into signed tetrahedra")
    w(" * (not Mirtich's method), each printed with 17 significant digits of the exact")
    w(" * rational. Inertia follows polymass.h: I = integral (|r|^2 Id - r r^T) dV,")
    w(" * row-major. surface_area is NaN where it is not part of the reference. */")
    w("#ifndef POLYMASS_TESTS_EXACT_REFERENCE_H")
    w("#define POLYMASS_TESTS_EXACT_REFERENCE_H")
    w("")
    w("#include <math.h>")
    w("#include <stddef.h>")
    w("#include <stdint.h>")
    w("")
    w("typedef struct pm_reference_solid {")
    w("    const char* name;")
    w("    const char* description;")
    w("    const double* positions; /* x, y, z per vertex, all exact in double */")
    w("    uint32_t vertex_count;")
    w("    const uint32_t* indices;")
    w("    uint32_t index_count;")
    w("    const uint32_t* face_sizes; /* NULL: all triangles */")
    w("    uint32_t face_count;")
    w("    double volume;")
    w("    double center_of_mass[3];")
    w("    double inertia[9];        /* about the centre of mass */")
    w("    double inertia_origin[9]; /* about (0, 0, 0) */")
    w("    double surface_area;")
    w("} pm_reference_solid;")
    w("")
    for r in refs:
        m = r.mesh
        w("/* %s: %s */" % (m.name, m.comment))
        w("static const double pm_ref_%s_positions[] = {" % m.name)
        w(format_list(["%s, %s, %s" % tuple(c_exact_double(x) for x in v) for v in m.vertices], 2))
        w("};")
        idx = [str(i) for f in m.faces for i in f]
        w("static const uint32_t pm_ref_%s_indices[] = {" % m.name)
        w(format_list(idx, 16))
        w("};")
        if not m.all_triangles():
            w("static const uint32_t pm_ref_%s_face_sizes[] = {" % m.name)
            w(format_list([str(len(f)) for f in m.faces], 16))
            w("};")
        w("")
    w("enum {")
    for k, r in enumerate(refs):
        w("    PM_REF_%s = %d," % (r.mesh.name.upper(), k))
    w("    PM_REF_COUNT = %d" % len(refs))
    w("};")
    w("")
    w("static const pm_reference_solid pm_reference_solids[PM_REF_COUNT] = {")
    for r in refs:
        m = r.mesh
        fs = "pm_ref_%s_face_sizes" % m.name if not m.all_triangles() else "NULL"
        area = "NAN"
        if r.area is not None:
            area = c_double(F(r.area))
        w('    {"%s", "%s",' % (m.name, m.comment.replace('"', "'")))
        w(
            "     pm_ref_%s_positions, %d, pm_ref_%s_indices, %d, %s, %d,"
            % (m.name, len(m.vertices), m.name, sum(len(f) for f in m.faces), fs, len(m.faces))
        )
        w("     /* volume = %s */" % r.volume)
        w("     %s," % c_double(r.volume))
        w("     {%s}," % ", ".join(c_double(x) for x in r.com))
        w("     {%s}," % ", ".join(c_double(x) for row in r.inertia for x in row))
        w("     {%s}," % ", ".join(c_double(x) for row in r.inertia_origin for x in row))
        w("     %s}," % area)
    w("};")
    w("")
    w("#endif /* POLYMASS_TESTS_EXACT_REFERENCE_H */")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", type=Path, default=DEFAULT_OUTPUT)
    parser.add_argument(
        "--check",
        action="store_true",
        help="fail if the output file differs from what would be written",
    )
    args = parser.parse_args()
    refs = [Reference(m) for m in build_solids()]
    self_check(refs)
    text = render(refs)
    if args.check:
        current = args.output.read_text() if args.output.exists() else ""
        if current != text:
            print("%s is out of date: run %s" % (args.output, Path(__file__).name), file=sys.stderr)
            return 1
        print("%s is up to date (%d solids)" % (args.output, len(refs)))
        return 0
    args.output.write_text(text)
    print("wrote %s (%d solids)" % (args.output, len(refs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
