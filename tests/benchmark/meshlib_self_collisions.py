"""MeshLib's self-intersection check, timed for bench_intersections.

Usage: python meshlib_self_collisions.py MESH ROUNDS
MESH: two uint64 counts (vertices, triangles), then the positions (float64
x, y, z each) and the triangles (uint32 three each), as bench_intersections
writes them. Prints the median seconds of mrmeshpy.findSelfCollidingTriangles
over ROUNDS runs, each on a mesh built anew (its box tree, which MeshLib
builds on first use, is in the time, as polymass's is), and the pairs found.
MeshLib holds single-precision coordinates, which 1e6 from the origin are
1/16 apart: the mesh is moved to its bounding box's centre first, as a user
of it would. Run it on one processor (taskset -c 0) for a single-thread rate.
"""

import statistics
import sys
import time

import numpy as np
from meshlib import mrmeshnumpy, mrmeshpy


def main() -> None:
    path, rounds = sys.argv[1], int(sys.argv[2])
    with open(path, "rb") as file:
        vertices, triangles = np.fromfile(file, dtype=np.uint64, count=2)
        positions = np.fromfile(file, dtype=np.float64, count=3 * int(vertices))
        faces = np.fromfile(file, dtype=np.uint32, count=3 * int(triangles))
    positions = positions.reshape(-1, 3)
    positions = positions - 0.5 * (positions.min(axis=0) + positions.max(axis=0))
    faces = faces.reshape(-1, 3).astype(np.int32)
    seconds, pairs = [], 0
    for _ in range(rounds):
        mesh = mrmeshnumpy.meshFromFacesVerts(faces, positions)
        start = time.perf_counter()
        found = mrmeshpy.findSelfCollidingTriangles(mrmeshpy.MeshPart(mesh))
        seconds.append(time.perf_counter() - start)
        pairs = found.size()
    print(f"{statistics.median(seconds):.6f} {pairs}")


if __name__ == "__main__":
    main()
