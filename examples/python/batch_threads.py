"""Mass properties of many meshes at once, on a thread pool.

    python examples/python/batch_threads.py [mesh files...] [--threads N]

polymass releases the GIL while the C library computes, so plain threads run
in parallel: no process pool, no pickling of large arrays. Without files, a
batch of 48 generated parts (spheres, capsules, tori, boxes in random poses)
stands in for a dataset.
"""

from __future__ import annotations

import argparse
import os
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import trimesh

import polymass


def generated_parts(count: int) -> list[tuple[str, np.ndarray, np.ndarray]]:
    rng = np.random.default_rng(2024)
    makers = {
        "sphere": lambda: trimesh.creation.icosphere(subdivisions=5, radius=rng.uniform(0.5, 2)),
        "capsule": lambda: trimesh.creation.capsule(height=rng.uniform(1, 3), count=[64, 64]),
        "torus": lambda: trimesh.creation.torus(
            major_radius=2.0,
            minor_radius=rng.uniform(0.2, 0.8),
            major_sections=256,
            minor_sections=128,
        ),
        "box": lambda: trimesh.creation.box(extents=rng.uniform(0.5, 3, size=3)),
    }
    parts = []
    for k in range(count):
        kind = list(makers)[k % len(makers)]
        mesh = makers[kind]()
        mesh.apply_transform(trimesh.transformations.random_rotation_matrix(rng.random(3)))
        mesh.apply_translation(rng.uniform(-1e3, 1e3, size=3))
        parts.append((f"{kind}-{k}", np.asarray(mesh.vertices), np.asarray(mesh.faces, np.uint32)))
    return parts


def loaded_parts(paths: list[str]) -> list[tuple[str, np.ndarray, np.ndarray]]:
    parts = []
    for path in paths:
        mesh = trimesh.load(path, force="mesh", process=False)
        parts.append((path, np.asarray(mesh.vertices), np.asarray(mesh.faces, np.uint32)))
    return parts


def properties(part):
    name, vertices, faces = part
    try:
        return name, len(faces), polymass.mass_properties(vertices, faces, weld=True), None
    except polymass.Error as error:  # one bad mesh does not stop the batch
        return name, len(faces), None, error


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("meshes", nargs="*")
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    arguments = parser.parse_args()
    parts = loaded_parts(arguments.meshes) if arguments.meshes else generated_parts(48)
    triangles = sum(len(faces) for _, _, faces in parts)

    start = time.perf_counter()
    serial = [properties(part) for part in parts]
    serial_time = time.perf_counter() - start
    start = time.perf_counter()
    with ThreadPoolExecutor(arguments.threads) as pool:
        results = list(pool.map(properties, parts))
    threaded_time = time.perf_counter() - start

    for name, count, p, error in results:
        if error:
            print(f"{name:14s} {count:8d} triangles  {type(error).__name__}: {error.message}")
        else:
            print(
                f"{name:14s} {count:8d} triangles  volume {p.volume:11.6f}  "
                f"centre {np.array2string(p.center_of_mass, precision=4)}  "
                f"I1 {p.principal_moments[0]:.6g}"
            )
    same = all(
        (a[2] is None and b[2] is None) or (a[2].inertia == b[2].inertia).all()
        for a, b in zip(serial, results)
    )
    print(
        f"\n{len(parts)} meshes, {triangles:,} triangles: serial {serial_time * 1e3:.0f} ms, "
        f"{arguments.threads} threads {threaded_time * 1e3:.0f} ms "
        f"({serial_time / threaded_time:.2f}x); results identical: {same}"
    )


if __name__ == "__main__":
    main()
