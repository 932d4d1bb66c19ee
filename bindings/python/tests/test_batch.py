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
