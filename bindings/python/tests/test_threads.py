"""Threads: concurrent computations give the results of serial ones, bit for bit."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

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


def test_library_threads_give_the_bits_of_one():
    vertices, faces = torus(3.0, 1.0, 400, 200)  # 160k triangles: several blocks of faces
    vertices = vertices + 1e5
    one = polymass.mass_properties(vertices, faces, threads=1)
    report = polymass.check(vertices, faces)
    for threads in (2, 3, 7):
        many = polymass.mass_properties(vertices, faces, threads=threads)
        assert _fingerprint(many) == _fingerprint(one)
        assert many.error_bound == one.error_bound
        assert polymass.check(vertices, faces, threads=threads) == report
        assert np.array_equal(
            polymass.Mesh(vertices, faces, threads=threads).shell_of_face,
            polymass.Mesh(vertices, faces).shell_of_face,
        )


def test_library_threads_are_checked():
    vertices, faces = torus(3.0, 1.0, 12, 8)
    for threads in (0, -2, 2.0, True):
        with pytest.raises(ValueError, match="threads must be a positive integer"):
            polymass.mass_properties(vertices, faces, threads=threads)
    with pytest.raises(polymass.InvalidArgumentError, match="threads"):
        polymass.mass_properties(vertices, faces, threads=10**6)
