"""Property-based tests of the laws mass properties obey, on random solids."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import polymass
from shapes import ROTATIONS, SHAPES

RELATIVE = 1e-12

shapes = st.sampled_from(sorted(SHAPES))
seeds = st.integers(min_value=0, max_value=2**32 - 1)


def _solid(shape: str, seed: int):
    return SHAPES[shape](np.random.default_rng(seed))


def _close(actual, expected, relative=RELATIVE):
    scale = np.max(np.abs(expected))
    np.testing.assert_allclose(actual, expected, rtol=0, atol=relative * scale)


@given(shapes, seeds, st.floats(min_value=-1e7, max_value=1e7), st.integers(0, 2))
def test_translation_moves_the_centre_and_keeps_the_central_tensor(shape, seed, distance, axis):
    vertices, faces = _solid(shape, seed)
    shift = np.zeros(3)
    shift[axis] = distance
    moved = polymass.mass_properties(vertices + shift, faces)
    still = polymass.mass_properties(vertices, faces)
    # Translating by t rounds each coordinate by up to ulp(|t|) / 2, which changes the
    # solid by that much relative to its size (about 1): allow a few such roundings.
    size = np.max(np.abs(vertices))
    relative = max(RELATIVE, 8 * np.spacing(abs(distance)) / size)
    _close(moved.inertia, still.inertia, relative)
    np.testing.assert_allclose(
        moved.center_of_mass - shift, still.center_of_mass, rtol=0, atol=relative * size
    )
    _close(moved.volume, still.volume, relative)


@given(shapes, seeds)
def test_rotation_rotates_the_central_tensor(shape, seed):
    rng = np.random.default_rng(seed)
    vertices, faces = SHAPES[shape](rng)
    rotation = ROTATIONS[shape](rng)
    turned = polymass.mass_properties(vertices @ rotation.T, faces)
    still = polymass.mass_properties(vertices, faces)
    _close(turned.inertia, rotation @ still.inertia @ rotation.T, 1e-11)
    _close(turned.center_of_mass, rotation @ still.center_of_mass, 1e-11)
    _close(turned.principal_moments, still.principal_moments, 1e-11)


@given(shapes, seeds, st.floats(min_value=1e-6, max_value=1e6))
def test_scaling_by_s_scales_volume_by_s3_and_inertia_by_s5(shape, seed, s):
    vertices, faces = _solid(shape, seed)
    scaled = polymass.mass_properties(vertices * s, faces)
    unit = polymass.mass_properties(vertices, faces)
    _close(scaled.volume, unit.volume * s**3)
    _close(scaled.inertia, unit.inertia * s**5)
    _close(scaled.surface_area, unit.surface_area * s**2)


@given(shapes, shapes, seeds)
def test_disjoint_solids_add(first, second, seed):
    a_vertices, a_faces = _solid(first, seed)
    b_vertices, b_faces = _solid(second, seed + 1)
    b_vertices = b_vertices + np.array([10.0, 0.0, 0.0])  # every shape fits in a radius-5 ball
    a = polymass.mass_properties(a_vertices, a_faces, about="origin")
    b = polymass.mass_properties(b_vertices, b_faces, about="origin")
    both_vertices = np.vstack([a_vertices, b_vertices])
    both_faces = [list(f) for f in a_faces] + [
        list(np.asarray(f) + len(a_vertices)) for f in b_faces
    ]
    both = polymass.mass_properties(both_vertices, both_faces, about="origin")
    _close(both.volume, a.volume + b.volume)
    _close(both.inertia_origin, a.inertia_origin + b.inertia_origin)
    _close(both.center_of_mass * both.mass, a.center_of_mass * a.mass + b.center_of_mass * b.mass)
    _close(both.surface_area, a.surface_area + b.surface_area)


@given(shapes, seeds)
def test_reversed_faces_are_reported_as_inverted_or_turned(shape, seed):
    vertices, faces = _solid(shape, seed)
    reversed_faces = [list(face)[::-1] for face in faces]
    with pytest.raises(polymass.InvertedError):
        polymass.mass_properties(vertices, reversed_faces)
    turned = polymass.mass_properties(vertices, reversed_faces, accept_inverted=True)
    right = polymass.mass_properties(vertices, faces)
    assert turned.warnings & polymass.Warnings.INVERTED
    _close(turned.volume, right.volume)
    _close(turned.inertia, right.inertia)
    assert polymass.check(vertices, reversed_faces).signed_volume < 0


@given(shapes, seeds, st.floats(min_value=0.1, max_value=100))
def test_principal_axes_are_a_right_handed_eigenbasis(shape, seed, density):
    vertices, faces = _solid(shape, seed)
    p = polymass.mass_properties(vertices, faces, density=density)
    axes = p.principal_axes
    np.testing.assert_allclose(axes.T @ axes, np.eye(3), atol=1e-14)
    assert np.linalg.det(axes) == pytest.approx(1.0, abs=1e-14)
    _close(axes @ np.diag(p.principal_moments) @ axes.T, p.inertia)
    assert np.all(np.diff(p.principal_moments) >= 0)
