#!/usr/bin/env python3
"""Writes the meshes bundled with polymass and their exact mass properties.

    python3 examples/data/generate.py        (rewrites the files beside it)

Every coordinate is a small dyadic rational, so float32 (binary STL) and
float64 hold it exactly, and the expected values are computed here in exact
rational arithmetic (fractions): each face is fanned into triangles, each
triangle with the origin spans a signed tetrahedron, and the tetrahedra's
integrals add up to the solid's. The results go to expected.json for unit
density in the file's own length unit (millimetres for these parts).
"""

import json
import math
import struct
from fractions import Fraction
from pathlib import Path

HERE = Path(__file__).resolve().parent


def l_bracket():
    """An L-bracket: a non-convex hexagonal profile (40 x 30 mm, legs 8 mm
    thick) extruded 20 mm along z, placed away from the origin. Two hexagon
    caps and six quads: polygon faces, as a CAD export would write them."""
    profile = [(0, 0), (40, 0), (40, 8), (8, 8), (8, 30), (0, 30)]  # CCW seen from +z
    ox, oy, oz = 100, 50, -10
    depth = 20
    bottom = [(x + ox, y + oy, oz) for x, y in profile]
    top = [(x + ox, y + oy, oz + depth) for x, y in profile]
    vertices = bottom + top
    n = len(profile)
    faces = [list(reversed(range(n))), list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return vertices, faces


def plate_with_hole():
    """A 60 x 40 x 5 mm mounting plate with a 20 x 10 mm through-hole off its
    centre: each cap is four trapezoids around the hole, the hole's walls face
    inward. A solid of genus one with quad faces only."""
    ax, ay, t = 60, 40, 5
    hx0, hy0, hx1, hy1 = 30, 20, 50, 30
    outer = [(0, 0), (ax, 0), (ax, ay), (0, ay)]
    inner = [(hx0, hy0), (hx1, hy0), (hx1, hy1), (hx0, hy1)]
    vertices = [(x, y, 0) for x, y in outer + inner] + [(x, y, t) for x, y in outer + inner]
    # 0-3 outer bottom, 4-7 inner bottom, 8-11 outer top, 12-15 inner top
    faces = []
    for i in range(4):
        j = (i + 1) % 4
        faces.append([8 + i, 8 + j, 12 + j, 12 + i])  # top trapezoid, normal +z
        faces.append([i, 4 + i, 4 + j, j])  # bottom trapezoid, normal -z
        faces.append([i, j, 8 + j, 8 + i])  # outer wall
        faces.append([4 + i, 12 + i, 12 + j, 4 + j])  # hole wall, facing the hole
    return vertices, faces


def hollow_box():
    """A 40 mm cube shell with a 30 x 30 x 20 mm cavity off-centre: two
    shells, the inner one facing inward, so the solid is the material only."""

    def box(x0, y0, z0, x1, y1, z1, outward):
        v = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
        quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
        return v, [q if outward else list(reversed(q)) for q in quads]

    outer_v, outer_f = box(0, 0, 0, 40, 40, 40, True)
    inner_v, inner_f = box(5, 5, 12, 35, 35, 32, False)
    return outer_v + inner_v, outer_f + [[i + 8 for i in f] for f in inner_f]


def robot_link():
    """A robot arm link: an octagonal bar 160 mm long along a tilted axis
    between two joints, triangulated as an STL exporter writes it. The
    octagon's corners are dyadic (a 'rounded square' of side 32 with 8 mm
    chamfers) and the bar is sheared so that the products of inertia are not
    zero."""
    octagon = [(8, 0), (24, 0), (32, 8), (32, 24), (24, 32), (8, 32), (0, 24), (0, 8)]
    length = 160
    rise = 40  # the far end sits 40 mm higher: a sheared (oblique) prism

    def at(x, corner):
        y, z = corner
        return (x, y - 16, z - 16 + Fraction(rise * x, length))

    near = [at(0, c) for c in octagon]
    far = [at(length, c) for c in octagon]
    vertices = near + far
    n = len(octagon)
    # The octagon is CCW seen from +x; the near cap faces -x, the far cap +x.
    faces = [[0, i + 1, i] for i in range(1, n - 1)]
    faces += [[n, n + i, n + i + 1] for i in range(1, n - 1)]
    for i in range(n):
        j = (i + 1) % n
        faces += [[i, j, n + j], [i, n + j, n + i]]
    return vertices, faces


def exact_properties(vertices, faces):
    """Volume, centre of mass, inertia about it and about the origin, and
    surface area of a closed, outward-oriented polyhedron, unit density."""
    v = [tuple(Fraction(c) for c in p) for p in vertices]
    volume = Fraction(0)
    first = [Fraction(0)] * 3
    second = [[Fraction(0)] * 3 for _ in range(3)]
    area = 0.0
    for face in faces:
        vector_area = [Fraction(0)] * 3
        for k in range(1, len(face) - 1):
            a, b, c = v[face[0]], v[face[k]], v[face[k + 1]]
            cross = (
                b[1] * c[2] - b[2] * c[1],
                b[2] * c[0] - b[0] * c[2],
                b[0] * c[1] - b[1] * c[0],
            )
            det = a[0] * cross[0] + a[1] * cross[1] + a[2] * cross[2]
            volume += det / 6
            for i in range(3):
                first[i] += det / 24 * (a[i] + b[i] + c[i])
                for j in range(3):
                    s = a[i] * a[j] + b[i] * b[j] + c[i] * c[j]
                    s += (a[i] + b[i] + c[i]) * (a[j] + b[j] + c[j])
                    second[i][j] += det / 120 * s
            ab = [b[i] - a[i] for i in range(3)]
            ac = [c[i] - a[i] for i in range(3)]
            tri = (
                ab[1] * ac[2] - ab[2] * ac[1],
                ab[2] * ac[0] - ab[0] * ac[2],
                ab[0] * ac[1] - ab[1] * ac[0],
            )
            for i in range(3):
                vector_area[i] += tri[i] / 2
        # A planar face's area is the length of its vector area.
        area += math.sqrt(sum(x * x for x in vector_area))
    com = [m / volume for m in first]
    trace = sum(second[i][i] for i in range(3))
    origin = [[(trace if i == j else 0) - second[i][j] for j in range(3)] for i in range(3)]
    com_second = [[second[i][j] - volume * com[i] * com[j] for j in range(3)] for i in range(3)]
    com_trace = sum(com_second[i][i] for i in range(3))
    about_com = [
        [(com_trace if i == j else 0) - com_second[i][j] for j in range(3)] for i in range(3)
    ]
    return {
        "volume": float(volume),
        "center_of_mass": [float(c) for c in com],
        "inertia": [[float(x) for x in row] for row in about_com],
        "inertia_origin": [[float(x) for x in row] for row in origin],
        "surface_area": area,
        "vertices": len(vertices),
        "faces": len(faces),
    }


def number(x):
    x = Fraction(x)
    return str(x.numerator) if x.denominator == 1 else repr(float(x))


def write_obj(path, vertices, faces, about):
    lines = [f"# {line}" for line in about.splitlines()]
    lines += ["# generated by generate.py; lengths in millimetres"]
    lines += ["v " + " ".join(number(c) for c in p) for p in vertices]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def write_binary_stl(path, vertices, faces):
    header = b"polymass example robot link, millimetres, generate.py".ljust(80, b" ")
    body = [header, struct.pack("<I", len(faces))]
    for f in faces:
        body.append(struct.pack("<3f", 0.0, 0.0, 0.0))  # normals are not read
        for i in f:
            body.append(struct.pack("<3f", *(float(c) for c in vertices[i])))
        body.append(b"\0\0")
    path.write_bytes(b"".join(body))


def main():
    meshes = {
        "bracket.obj": (l_bracket, write_obj),
        "plate_with_hole.obj": (plate_with_hole, write_obj),
        "hollow_box.obj": (hollow_box, write_obj),
        "robot_link.stl": (robot_link, None),
    }
    expected = {}
    for name, (make, writer) in meshes.items():
        vertices, faces = make()
        if name.endswith(".stl"):
            write_binary_stl(HERE / name, vertices, faces)
        else:
            writer(HERE / name, vertices, faces, make.__doc__.strip())
        expected[name] = exact_properties(vertices, faces)
        expected[name]["description"] = " ".join(make.__doc__.split())
    (HERE / "expected.json").write_text(json.dumps(expected, indent=2) + "\n")


if __name__ == "__main__":
    main()
