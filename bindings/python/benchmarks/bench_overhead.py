"""What the Python binding adds to the C call, on a 1,000,000-triangle torus.

    python bindings/python/benchmarks/bench_overhead.py [--triangles N] [--repeat N]

Times, interleaved and each as the median of N runs: the C function itself
(polymass_mass_properties_compute with its provenance, called through cffi on
arrays already described, with default options: what a C caller pays, plus the
call's sub-microsecond cffi cost) and `polymass.mass_properties` on the same
NumPy arrays (describing them, gathering and translating the options, the
call, building the result). Prints the figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import polymass
from polymass._arrays import mesh_description
from polymass._library import ffi, lib, new_struct, working_context

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from shapes import torus


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--triangles", type=float, default=1e6)
    parser.add_argument("--repeat", type=int, default=21)
    arguments = parser.parse_args()
    side = int(np.sqrt(arguments.triangles / 2))
    vertices, faces = torus(3.0, 1.0, side, side)
    faces = np.ascontiguousarray(faces, dtype=np.uint32)
    vertices = np.ascontiguousarray(vertices + 1e3)
    description = mesh_description(vertices, faces, None)
    ctx = working_context(None)  # one thread, as mass_properties uses by default
    out = new_struct("polymass_mass_properties")
    provenance = new_struct("polymass_provenance")

    def c_call() -> None:
        status = lib.polymass_mass_properties_compute(
            out, provenance, ctx, description.desc, ffi.NULL, ffi.NULL
        )
        if status != 0:
            raise RuntimeError(ffi.string(lib.polymass_context_message(ctx)).decode())

    def python_call() -> None:
        polymass.mass_properties(vertices, faces)

    times: dict[str, list[float]] = {"C": [], "Python": []}
    for _ in range(arguments.repeat):
        for name, call in (("C", c_call), ("Python", python_call)):
            start = time.perf_counter()
            call()
            times[name].append(time.perf_counter() - start)
    c, python = statistics.median(times["C"]), statistics.median(times["Python"])
    print(f"{faces.shape[0]:,} triangles, median of {arguments.repeat} interleaved runs")
    print(f"  C call:          {c * 1e3:8.3f} ms")
    print(f"  Python binding:  {python * 1e3:8.3f} ms")
    print(f"  overhead:        {(python - c) * 1e3:8.3f} ms = {100 * (python - c) / c:.2f} %")


if __name__ == "__main__":
    main()
