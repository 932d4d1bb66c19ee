"""Meshes generated for the --html page tests and load-time figures."""

import math
import struct


def sphere_triangles(rings, segments):
    """A unit sphere's triangles, counter-clockwise seen from outside."""

    def point(i, j):
        theta, phi = math.pi * i / rings, 2 * math.pi * j / segments
        return (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))

    triangles = []
    for i in range(rings):
        for j in range(segments):
            a, b, c, d = point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)
            if i > 0:
                triangles.append((a, b, d))
            if i < rings - 1:
                triangles.append((b, c, d))
    return triangles


def write_binary_stl(path, triangles):
    record = struct.Struct("<12fH")
    with open(path, "wb") as out:
        out.write(b"\0" * 80 + struct.pack("<I", len(triangles)))
        for a, b, c in triangles:
            out.write(record.pack(0.0, 0.0, 0.0, *a, *b, *c, 0))
    return path
