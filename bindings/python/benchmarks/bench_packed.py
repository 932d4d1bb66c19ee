"""Meshes/s of the packed call from Python, on the C benchmark's workload.

    python bindings/python/benchmarks/bench_packed.py [--meshes N] [--faces N] [--rounds N]
        [--checks default|topology|trusted]

The workload of tests/benchmark/bench_batch.c: closed latitude-longitude
spheres of 1,000 triangles (default 5,000 of them), each at its own place, in
one packed array, with the options named as bench_batch takes them (default:
the default options; "topology": no intersection check; "trusted": no check,
where the per-mesh costs around the computation weigh most). Times, interleaved and each as the
median of the rounds, on one thread and on two: the C function itself
(polymass_packed_compute called through cffi on the arrays already described:
what a C caller pays, the bound of this run), `polymass.packed_mass_properties`
on the same NumPy arrays (int64 global indices as PyTorch3D packs them, and
uint32 local ones), and `polymass.batch` on a list of (vertices, faces) views
(a mesh at a time, as before the packed call). Prints meshes/s and the ratios;
asserts nothing about speed (the results are checked equal).
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import polymass
from polymass._library import ffi, lib, new_struct, working_context
from polymass._options import c_options as options_struct


def sphere(rings: int, segments: int) -> tuple[np.ndarray, np.ndarray]:
    """bench_batch.c's closed sphere: 2 poles and segments - 1 rings of ``rings``
    vertices, 2 * rings * (segments - 1) triangles, outward."""
    theta = np.pi * np.arange(1, segments) / segments
    phi = 2 * np.pi * np.arange(rings) / rings
    ring_points = np.stack(
        [
            np.outer(np.sin(theta), np.cos(phi)),
            np.outer(np.sin(theta), np.sin(phi)),
            np.repeat(np.cos(theta), rings).reshape(-1, rings),
        ],
        axis=-1,
    ).reshape(-1, 3)
    vertices = np.vstack([[0.0, 0.0, 1.0], ring_points, [0.0, 0.0, -1.0]])
    south = 1 + (segments - 1) * rings
    j = np.arange(rings)
    a, b = 1 + j, 1 + (j + 1) % rings
    c, d = 1 + (segments - 2) * rings + j, 1 + (segments - 2) * rings + (j + 1) % rings
    caps = np.concatenate(
        [np.stack([np.zeros(rings, int), a, b], -1), np.stack([np.full(rings, south), d, c], -1)]
    )
    i = np.arange(segments - 2)[:, None]
    a = 1 + i * rings + j
    b = 1 + i * rings + (j + 1) % rings
    c, d = a + rings, b + rings
    band = np.concatenate(
        [np.stack([a, c, d], -1).reshape(-1, 3), np.stack([a, d, b], -1).reshape(-1, 3)]
    )
    return vertices, np.concatenate([caps, band])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--meshes", type=int, default=5000)
    parser.add_argument("--faces", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--checks", choices=("default", "topology", "trusted"), default="default")
    arguments = parser.parse_args()
    options = {
        "default": polymass.Options(),
        "topology": polymass.Options(skip_intersection_check=True),
        "trusted": polymass.Options(skip_checks=True),
    }[arguments.checks]
    c_options = options_struct(options)
    count, segments = arguments.meshes, 11
    rings = max(arguments.faces // 20, 3)
    one_vertices, one_faces = sphere(rings, segments)
    nv, nf = len(one_vertices), len(one_faces)
    shift = np.zeros((count, 1, 3))
    shift[:, 0, 0] = 3.0 * np.arange(count)
    vertices = (one_vertices[None] + shift).reshape(-1, 3)
    local = np.tile(one_faces, (count, 1)).astype(np.uint32)
    first = np.repeat(np.arange(count, dtype=np.int64) * nv, nf)[:, None]
    global_int64 = local.astype(np.int64) + first  # PyTorch3D's faces_packed
    vertex_offsets = np.arange(count + 1, dtype=np.int64) * nv
    face_offsets = np.arange(count + 1, dtype=np.int64) * nf
    meshes = [(vertices[m * nv : (m + 1) * nv], local[m * nf : (m + 1) * nf]) for m in range(count)]

    # The C call on the arrays described once.
    c_meshes = new_struct("polymass_packed_meshes")
    c_meshes.positions = ffi.from_buffer(vertices)
    c_meshes.indices = ffi.from_buffer(local)
    c_meshes.mesh_count = count
    c_vertex_offsets = ffi.from_buffer("uint64_t[]", vertex_offsets.astype(np.uint64))
    c_index_offsets = ffi.from_buffer("uint64_t[]", (3 * face_offsets).astype(np.uint64))
    c_meshes.vertex_offsets, c_meshes.index_offsets = c_vertex_offsets, c_index_offsets
    c_volume = np.empty(count)
    c_results = new_struct("polymass_packed_results")
    c_results.volume = ffi.cast("double*", ffi.from_buffer(c_volume, require_writable=True))
    failed = ffi.new("uint64_t*")

    def c_call(threads: int) -> np.ndarray:
        ctx = working_context(threads)
        status = lib.polymass_packed_compute(c_results, failed, ctx, c_meshes, c_options)
        if status != 0 or failed[0]:
            raise RuntimeError(ffi.string(lib.polymass_context_message(ctx)).decode())
        return c_volume

    def packed_global(threads: int) -> np.ndarray:
        return polymass.packed_mass_properties(
            vertices,
            global_int64,
            vertex_offsets,
            face_offsets,
            global_indices=True,
            threads=threads,
            options=options,
        ).volume

    def packed_local(threads: int) -> np.ndarray:
        return polymass.packed_mass_properties(
            vertices, local, vertex_offsets, face_offsets, threads=threads, options=options
        ).volume

    def old_batch(threads: int) -> np.ndarray:
        return np.array(
            [p.volume for p in polymass.batch(meshes, threads=threads, options=options)]
        )

    paths = {
        "C packed call (cffi)": c_call,
        "packed_mass_properties, int64 global": packed_global,
        "packed_mass_properties, uint32 local": packed_local,
        "polymass.batch (a mesh at a time)": old_batch,
    }
    times: dict[tuple[str, int], list[float]] = {}
    expected = None
    for _ in range(arguments.rounds):
        for name, call in paths.items():
            for threads in (1, 2):
                start = time.perf_counter()
                volumes = call(threads)
                times.setdefault((name, threads), []).append(time.perf_counter() - start)
                if expected is None:
                    expected = volumes.copy()
                elif volumes.tobytes() != expected.tobytes():
                    raise RuntimeError(f"{name} on {threads} threads: other volumes")

    rate = {key: count / statistics.median(values) for key, values in times.items()}
    print(
        f"polymass {polymass.__version__}: {count:,} closed meshes of {nf:,} triangles, "
        f"{arguments.checks} options, median of {arguments.rounds} interleaved rounds"
    )
    c_rates = (rate[("C packed call (cffi)", 1)], rate[("C packed call (cffi)", 2)])
    for name in paths:
        one, two = rate[(name, 1)], rate[(name, 2)]
        print(
            f"  {name:38s} 1 thread {one:8.0f} meshes/s ({one / c_rates[0]:.2f} of C)  "
            f"2 threads {two:8.0f} meshes/s ({two / c_rates[1]:.2f} of C, {two / one:.2f}x)"
        )
    old = rate[("polymass.batch (a mesh at a time)", 1)]
    new = rate[("packed_mass_properties, int64 global", 1)]
    print(f"  packed (int64 global) / polymass.batch, 1 thread: {new / old:.2f}")
    print("  every path's volumes bit for bit the same")


if __name__ == "__main__":
    main()
