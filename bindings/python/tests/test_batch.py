"""polymass.batch: results in order, bit for bit those of single calls, with
per-item errors that do not stop the others."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from shapes import SHAPES


def _meshes():
    rng = np.random.default_rng(11)
    return [SHAPES[name](rng) for name in ("star", "hull", "extrusion", "star")]


def test_batch_equals_single_calls_bit_for_bit():
    meshes = _meshes()
    densities = [1.0, 2700.0, 7850.0, 0.5]
    results = polymass.batch(meshes, density=densities, about="origin")
    for (vertices, faces), density, result in zip(meshes, densities, results):
        single = polymass.mass_properties(vertices, faces, density=density, about="origin")
        assert isinstance(result, polymass.MassProperties)
        assert result.mass == single.mass and result.volume == single.volume
        assert np.array_equal(result.inertia, single.inertia)
        assert np.array_equal(result.inertia_point, single.inertia_point)
        assert np.array_equal(result.principal_axes, single.principal_axes)
        assert result.error_bound == single.error_bound


def test_errors_stay_with_their_item():
    meshes = _meshes()
    vertices, faces = meshes[1]
    open_surface = (vertices, np.asarray(faces)[1:])
    out_of_range = (vertices, np.asarray(faces, dtype=np.int64) + len(vertices))
    negative = (vertices, -np.ones((4, 3), dtype=np.int32))
    results = polymass.batch([meshes[0], open_surface, out_of_range, negative, meshes[2]])
    assert isinstance(results[0], polymass.MassProperties)
    assert isinstance(results[1], polymass.OpenSurfaceError) and "edge" in str(results[1])
    assert isinstance(results[2], polymass.IndexOutOfRangeError)
    assert isinstance(results[3], polymass.IndexOutOfRangeError)
    assert isinstance(results[4], polymass.MassProperties)


def test_per_item_values_are_checked():
    with pytest.raises(ValueError, match="density has 1 values for 2 meshes"):
        polymass.batch(_meshes()[:2], density=[1.0])
    assert polymass.batch([]) == []


def test_threads_give_the_results_of_one_thread():
    rng = np.random.default_rng(12)
    meshes = [SHAPES[name](rng) for name in sorted(SHAPES) for _ in range(6)]
    vertices, faces = SHAPES["hull"](rng)
    meshes[5] = (vertices, np.asarray(faces)[1:])  # open: its error stays at its place
    densities = np.linspace(1.0, 3.0, len(meshes))
    serial = polymass.batch(meshes, density=densities, about=(1.0, 2.0, 3.0))
    for threads in (2, 3, 8):
        threaded = polymass.batch(meshes, density=densities, about=(1.0, 2.0, 3.0), threads=threads)
        assert len(threaded) == len(serial)
        for one, many in zip(serial, threaded):
            assert type(one) is type(many)
            if isinstance(one, polymass.Error):
                assert str(one) == str(many)
                continue
            assert one.mass == many.mass and one.volume == many.volume
            assert np.array_equal(one.inertia_point, many.inertia_point)
            assert np.array_equal(one.principal_axes, many.principal_axes)
            assert one.error_bound == many.error_bound
    assert isinstance(serial[5], polymass.OpenSurfaceError)


def test_threads_must_be_a_positive_integer():
    for threads in (0, -1, 1.5, True, "2"):
        with pytest.raises(ValueError, match="threads must be a positive integer"):
            polymass.batch(_meshes(), threads=threads)
    assert polymass.batch([], threads=4) == []
