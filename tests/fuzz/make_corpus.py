#!/usr/bin/env python3
"""Writes the seed corpus of tests/fuzz/fuzz_mesh.c into tests/fuzz/corpus/,
and the hand-made regression inputs into tests/fuzz/regressions/.

Each file is a small mesh encoded in the harness's input format (described at
the top of fuzz_mesh.c). The output is deterministic; the files are committed,
so run this again only after changing the format or the meshes:

    python3 tests/fuzz/make_corpus.py            # writes corpus/*.bin, regressions/made_*.bin
    python3 tests/fuzz/make_corpus.py --check    # exit 1 if the files differ

(regressions/ also holds inputs the fuzzer found: those are not written here.)
"""

import argparse
import math
import pathlib
import struct
import sys

HERE = pathlib.Path(__file__).resolve().parent

# Option flags (polymass.h)
SKIP_TOPOLOGY_CHECKS = 1 << 0
ACCEPT_INVERTED = 1 << 1
WELD_VERTICES = 1 << 2
ACCEPT_NON_MANIFOLD = 1 << 3
# The harness inverts bit 4 (POLYMASS_OPTION_SKIP_INTERSECTION_CHECK): set, it asks
# for the intersection check, as when the corpus was written.
CHECK_INTERSECTIONS = 1 << 4

# Mass modes of the harness (header byte 3)
MASS_NULL, MASS_DENSITY, MASS_TOTAL = 0, 1, 2

# Stride choices of the harness (layout bits 3-4)
STRIDE_PACKED, STRIDE_VERTEX, STRIDE_PADDED, STRIDE_TOO_SMALL = 0, 1, 2, 3


def encode(
    vertices,
    faces,
    *,
    float32=False,
    index16=False,
    face_sizes=True,
    stride=STRIDE_PACKED,
    count_delta=None,
    packed_pairs=False,
    odd=False,
    flags=0,
    tolerance=0,
    mass_mode=MASS_NULL,
    mass_value=1.0,
    point=(0.0, 0.0, 0.0),
    copies=1,
):
    """One input of fuzz_mesh.c. faces: lists of vertex indices; without
    face_sizes every face must be a triangle."""
    assert len(vertices) <= 255 and len(faces) <= 255 and 1 <= copies <= 256
    if not face_sizes:
        assert all(len(face) == 3 for face in faces)
    layout = (
        int(float32)
        | int(index16) << 1
        | int(face_sizes) << 2
        | stride << 3
        | int(count_delta is not None) << 5
        | int(packed_pairs) << 6
        | int(odd) << 7
    )
    out = bytearray()
    out += bytes(
        [
            layout,
            flags,
            tolerance,
            mass_mode,
            len(vertices),
            len(faces),
            copies - 1,
            (count_delta or 0) & 0xFF,
        ]
    )
    out += struct.pack("<d", mass_value)
    out += struct.pack("<3d", *point)
    if face_sizes:
        out += bytes(len(face) for face in faces)
    for vertex in vertices:
        out += struct.pack("<3f" if float32 else "<3d", *vertex)
    for face in faces:
        for index in face:
            out += struct.pack("<H" if index16 else "<I", index)
    return bytes(out)


# --- meshes -------------------------------------------------------------------

CUBE_VERTICES = [((i & 1) * 1.0, (i >> 1 & 1) * 1.0, (i >> 2 & 1) * 1.0) for i in range(8)]
# Counter-clockwise seen from outside.
CUBE_QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def triangulate(faces):
    return [[face[0], face[i], face[i + 1]] for face in faces for i in range(1, len(face) - 1)]


CUBE_TRIANGLES = triangulate(CUBE_QUADS)

TETRA_VERTICES = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TETRA_FACES = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def prism(profile, height):
    """A prism over a counter-clockwise planar profile: two n-gons and n quads."""
    n = len(profile)
    vertices = [(x, y, 0.0) for x, y in profile] + [(x, y, height) for x, y in profile]
    faces = [list(reversed(range(n))), list(range(n, 2 * n))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return vertices, faces


L_PROFILE = [(0.0, 0.0), (3.0, 0.0), (3.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)]


def seeds():
    # A unit cube of quads: the plainest valid input.
    yield "cube_quads", encode(CUBE_VERTICES, CUBE_QUADS)
    # The same cube as 12 triangles, float32 positions in an interleaved
    # buffer, 16-bit indices, a density and a reference point.
    yield (
        "cube_triangles",
        encode(
            CUBE_VERTICES,
            CUBE_TRIANGLES,
            float32=True,
            index16=True,
            face_sizes=False,
            stride=STRIDE_PADDED,
            mass_mode=MASS_DENSITY,
            mass_value=2700.0,
            point=(1.0, 2.0, 3.0),
        ),
    )
    # A tetrahedron given a total mass, arrays at odd addresses.
    yield (
        "tetrahedron",
        encode(
            TETRA_VERTICES,
            TETRA_FACES,
            index16=True,
            face_sizes=False,
            stride=STRIDE_VERTEX,
            odd=True,
            mass_mode=MASS_TOTAL,
            mass_value=2.0,
            point=(0.5, -1.0, 4.0),
        ),
    )
    # A box without its top: OPEN.
    yield "open_box", encode(CUBE_VERTICES, CUBE_QUADS[:1] + CUBE_QUADS[2:])
    # A tetrahedron with a NaN coordinate: NON_FINITE (and for the polygon).
    nan_vertices = list(TETRA_VERTICES)
    nan_vertices[3] = (0.0, math.nan, 1.0)
    yield "tetrahedron_nan", encode(nan_vertices, TETRA_FACES, mass_mode=MASS_DENSITY)
    # An inside-out cube, accepted turned.
    yield (
        "cube_inverted",
        encode(
            CUBE_VERTICES,
            [list(reversed(f)) for f in CUBE_QUADS],
            flags=ACCEPT_INVERTED,
            packed_pairs=True,
        ),
    )
    # An L-shaped prism: non-convex hexagon faces, float32, a tolerance.
    vertices, faces = prism(L_PROFILE, 0.5)
    yield (
        "l_prism",
        encode(vertices, faces, float32=True, tolerance=2, mass_mode=MASS_TOTAL, mass_value=10.0),
    )
    # Copies of the triangulated cube, all at one place (150 asked for, 56 under
    # fuzz_mesh.c's bound of 2048 indices), welded into one non-manifold
    # surface whose edges are balanced, and accepted as such.
    yield (
        "cube_copies_welded",
        encode(
            CUBE_VERTICES,
            CUBE_TRIANGLES,
            face_sizes=False,
            copies=150,
            flags=WELD_VERTICES | ACCEPT_NON_MANIFOLD,
        ),
    )
    # The same copies, each a shell of its own, topology checks skipped.
    yield (
        "cube_copies_unchecked",
        encode(
            CUBE_VERTICES,
            CUBE_TRIANGLES,
            face_sizes=False,
            copies=150,
            flags=SKIP_TOPOLOGY_CHECKS,
            index16=True,
        ),
    )
    # Two cubes overlapping by half, flush: coinciding faces of two shells.
    shifted = [(x + 0.5, y, z) for x, y, z in CUBE_VERTICES]
    yield (
        "cubes_overlapping_flush",
        encode(
            CUBE_VERTICES + shifted,
            CUBE_QUADS + [[v + 8 for v in f] for f in CUBE_QUADS],
            flags=CHECK_INTERSECTIONS,
        ),
    )
    # A double pyramid through the cube's top face along its own edges, its
    # lower apex on the cube's floor: no faces cross, the probes from inside
    # its triangles see it.
    waist = [(0.25, 0.25, 1.0), (0.75, 0.25, 1.0), (0.75, 0.75, 1.0), (0.25, 0.75, 1.0)]
    pyramid = [(0.5, 0.5, 2.0), (0.5, 0.5, 0.0)] + waist
    pyramid_faces = []
    for k in range(4):
        a, b = 10 + k, 10 + (k + 1) % 4
        pyramid_faces += [[8, a, b], [9, b, a]]
    yield (
        "pyramid_through_cube",
        encode(CUBE_VERTICES + pyramid, CUBE_QUADS + pyramid_faces, flags=CHECK_INTERSECTIONS),
    )
    # Faces of 0, 1 and 2 vertices and an index_count that does not add up.
    yield "small_faces", encode(TETRA_VERTICES, [[], [0], [1, 2]] + TETRA_FACES, count_delta=-2)


def scaled(vertices, factor, offset=(0.0, 0.0, 0.0)):
    return [tuple(c * factor + o for c, o in zip(vertex, offset)) for vertex in vertices]


def regressions():
    """Hand-made inputs for what the fuzzer found, each as plain as it gets."""
    # A valid cube of edge 1e-90 as 12 triangles: volume 1e-270, area 6e-180,
    # both representable; the triangle areas' squares (1e-360) are not.
    yield (
        "made_cube_triangles_1e-90_area_underflow",
        encode(scaled(CUBE_VERTICES, 1e-90), CUBE_TRIANGLES, face_sizes=False),
    )
    # A valid cube of edge 1e155 as quads: its bounding box diagonal (naive
    # norm) overflows, every face is taken as degenerate, and the surface is
    # accepted with volume 0.
    yield (
        "made_cube_quads_1e155_zero_volume_accepted",
        encode(scaled(CUBE_VERTICES, 1e155), CUBE_QUADS),
    )
    # One sliver triangle (edges 1.4 and 1e-200, area 7.1e-201), topology
    # checks skipped: it is reported degenerate and its area as 0, yet it
    # still adds its volume (8.3e-202).
    yield (
        "made_unchecked_sliver_triangle_area_zero",
        encode(
            [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (1e-300, 0.0, 1e-200)],
            [[0, 2, 1]],
            face_sizes=False,
            flags=SKIP_TOPOLOGY_CHECKS,
        ),
    )
    # A cube of edge 1e62: its second moments (1e310) overflow.
    yield "made_cube_1e62_moments_overflow", encode(scaled(CUBE_VERTICES, 1e62), CUBE_QUADS)
    # A cube of edge 2 of density 1e308: its mass overflows.
    yield (
        "made_cube_density_1e308_mass_overflow",
        encode(scaled(CUBE_VERTICES, 2.0), CUBE_QUADS, mass_mode=MASS_DENSITY, mass_value=1e308),
    )
    # The unit cube about a point at x = 1e200: its inertia about it overflows.
    yield (
        "made_cube_point_1e200_overflow",
        encode(
            CUBE_VERTICES,
            CUBE_QUADS,
            mass_mode=MASS_DENSITY,
            mass_value=1.0,
            point=(1e200, 0.0, 0.0),
        ),
    )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--check", action="store_true", help="compare with the files instead of writing them"
    )
    parser.add_argument("--out", type=pathlib.Path, default=HERE / "corpus")
    parser.add_argument("--regressions", type=pathlib.Path, default=HERE / "regressions")
    args = parser.parse_args()
    stale = []
    args.out.mkdir(parents=True, exist_ok=True)
    outputs = [(args.out / (name + ".bin"), data) for name, data in seeds()]
    outputs += [(args.regressions / (name + ".bin"), data) for name, data in regressions()]
    args.regressions.mkdir(parents=True, exist_ok=True)
    for path, data in outputs:
        if args.check:
            if not path.exists() or path.read_bytes() != data:
                stale.append(path)
        else:
            path.write_bytes(data)
    if stale:
        print("stale (run tests/fuzz/make_corpus.py):", *map(str, stale), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
