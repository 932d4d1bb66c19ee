"""Threads: concurrent computations give the results of serial ones, bit for bit."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np

import polymass
from shapes import SHAPES, torus

THREADS = 8


def _fingerprint(p: polymass.MassProperties) -> bytes:
    return b"".join(
        np.asarray(x, dtype=np.float64).tobytes()
        for x in (p.volume, p.center_of_mass, p.inertia, p.principal_axes, p.surface_area)
    )


def test_concurrent_mass_properties_are_identical_to_serial_ones():
    rng = np.random.default_rng(31)
    meshes = [SHAPES[name](rng) for name in sorted(SHAPES) for _ in range(4)]
    meshes.append(torus(3.0, 1.0, 300, 100))
    serial = [_fingerprint(polymass.mass_properties(v, f)) for v, f in meshes]
    work = meshes * 8
    with ThreadPoolExecutor(THREADS) as pool:
        concurrent = list(pool.map(lambda m: _fingerprint(polymass.mass_properties(*m)), work))
    assert concurrent == serial * 8


def test_one_mesh_read_by_many_threads():
    vertices, faces = torus(3.0, 1.0, 200, 100)
    mesh = polymass.Mesh(vertices, faces)
    densities = np.linspace(1.0, 10.0, 64)
    serial = [_fingerprint(mesh.mass_properties(density=d, about=(1, 2, 3))) for d in densities]
    with ThreadPoolExecutor(THREADS) as pool:
        concurrent = list(
            pool.map(
                lambda d: _fingerprint(mesh.mass_properties(density=d, about=(1, 2, 3))), densities
            )
        )
    assert concurrent == serial


def test_mesh_properties_equal_the_one_call_function():
    vertices, faces = SHAPES["extrusion"](np.random.default_rng(32))
    mesh = polymass.Mesh(vertices, faces)
    for density in (0.5, 2700.0):
        assert _fingerprint(mesh.mass_properties(density=density)) == _fingerprint(
            polymass.mass_properties(vertices, faces, density=density)
        )
