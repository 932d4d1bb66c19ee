"""Speed of polymass.mass_properties against trimesh on a 1,000,000-triangle torus,
and the accuracy of both on a unit cube moved far from the origin.

    python bindings/python/benchmarks/bench_vs_trimesh.py [--repeat N]

Prints the figures; asserts nothing (speed is measured here, never in the tests).
Each timing is the best of N runs. trimesh caches its results, so every trimesh
run gets a freshly built Trimesh (built outside the timed region, process=False).
"""

from __future__ import annotations

import argparse
import platform
import statistics
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import trimesh

import polymass

# The tests' torus: the same closed mesh the tests check, at benchmark size.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from shapes import torus


def unit_cube():
    vertices = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], float)
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    triangles = [[q[0], q[1], q[2]] for q in quads] + [[q[0], q[2], q[3]] for q in quads]
    return vertices, np.array(triangles)


def best_and_median(run, repeat: int, setup=lambda: None):
    times = []
    for _ in range(repeat):
        argument = setup()
        start = time.perf_counter()
        run(argument)
        times.append(time.perf_counter() - start)
    return min(times), statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    repeat = parser.parse_args().repeat

    vertices, faces32 = torus(3.0, 1.0, 1000, 500)
    faces = faces32.astype(np.int64)
    count = len(faces)
    print(
        f"polymass {polymass.__version__} (C library {polymass.library_version()}), "
        f"trimesh {trimesh.__version__}, numpy {np.__version__}, Python {platform.python_version()}"
    )
    print(f"torus: {count:,} triangles, {len(vertices):,} vertices; best / median of {repeat}\n")

    def fresh_trimesh():
        return trimesh.Trimesh(vertices, faces, process=False)

    rows = [
        (
            "polymass, checked, uint32 faces",
            lambda _: polymass.mass_properties(vertices, faces32),
            None,
        ),
        (
            "polymass, checked, int64 faces",
            lambda _: polymass.mass_properties(vertices, faces),
            None,
        ),
        (
            "polymass, skip_checks (trusted)",
            lambda _: polymass.mass_properties(vertices, faces32, skip_checks=True),
            None,
        ),
        ("trimesh mesh.mass_properties", lambda mesh: mesh.mass_properties, fresh_trimesh),
    ]
    results = {}
    for label, run, setup in rows:
        best, median = best_and_median(run, repeat, setup or (lambda: None))
        results[label] = best
        print(
            f"  {label:36s} {best * 1e3:8.1f} ms  {median * 1e3:8.1f} ms  "
            f"{count / best / 1e6:7.1f} M triangles/s"
        )
    trimesh_best = results["trimesh mesh.mass_properties"]
    print()
    for label in list(results)[:3]:
        print(f"  trimesh / ({label}): {trimesh_best / results[label]:.1f}x")

    # The GIL is released in the library: threads compute in parallel.
    threads = 2
    jobs = [None] * (2 * threads)
    start = time.perf_counter()
    for _ in jobs:
        polymass.mass_properties(vertices, faces32)
    serial = time.perf_counter() - start
    with ThreadPoolExecutor(threads) as pool:
        start = time.perf_counter()
        list(pool.map(lambda _: polymass.mass_properties(vertices, faces32), jobs))
        parallel = time.perf_counter() - start
    print(
        f"\n  {len(jobs)} computations: serial {serial * 1e3:.0f} ms, {threads} threads "
        f"{parallel * 1e3:.0f} ms ({serial / parallel:.2f}x)"
    )

    print(
        "\nunit cube moved to (t, t, t): relative error of Ixx about the centre of mass (exact 1/6)"
    )
    cube_vertices, cube_faces = unit_cube()
    for offset in (0.0, 1e4, 1e6, 1e8):
        ours = polymass.mass_properties(cube_vertices + offset, cube_faces).inertia[0, 0]
        theirs = trimesh.Trimesh(cube_vertices + offset, cube_faces, process=False).moment_inertia[
            0, 0
        ]
        print(
            f"  t = {offset:7.0e}:  polymass {abs(ours * 6 - 1):9.1e}"
            f"   trimesh {abs(theirs * 6 - 1):9.1e}"
        )


if __name__ == "__main__":
    main()
