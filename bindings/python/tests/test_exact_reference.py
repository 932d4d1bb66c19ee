"""Every quantity against the exact rational reference, for random solids placed
near the origin, far from it, rotated, and at tiny and huge scales."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from exact import assert_close, exact_solid
from shapes import ROTATIONS, SHAPES

RELATIVE = 1e-12

# (scale, offset): the offsets are where an origin-based integration loses its digits.
PLACEMENTS = {
    "unit": (1.0, 0.0),
    "far_1e6": (1.0, 1e6),
    "far_1e8": (1.0, 1e8),
    "tiny": (1e-9, 0.0),
    "huge": (1e9, 0.0),
    "tiny_far": (1e-3, 1e5),
}


def _placed(shape: str, placement: str, seed: int, rotate: bool):
    rng = np.random.default_rng(seed)
    vertices, faces = SHAPES[shape](rng)
    scale, offset = PLACEMENTS[placement]
    if rotate:
        vertices = vertices @ ROTATIONS[shape](rng).T
    direction = rng.normal(size=3)
    return vertices * scale + offset * direction / np.linalg.norm(direction), faces


def _assert_matches(properties: polymass.MassProperties, vertices, faces) -> None:
    exact = exact_solid(vertices, faces)
    assert_close(properties.volume, exact.volume, RELATIVE, "volume")
    assert_close(properties.center_of_mass, exact.center_of_mass, RELATIVE, "centre of mass")
    assert_close(properties.inertia, exact.inertia, RELATIVE, "inertia about the centre")
    assert_close(properties.inertia_origin, exact.inertia_origin, RELATIVE, "inertia about 0")
    assert_close(properties.surface_area, exact.surface_area, RELATIVE, "surface area")


@pytest.mark.parametrize("placement", PLACEMENTS)
@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_random_solids_match_the_exact_reference(shape, placement, seed):
    vertices, faces = _placed(shape, placement, seed, rotate=seed % 2 == 0)
    _assert_matches(polymass.mass_properties(vertices, faces), vertices, faces)


@pytest.mark.parametrize("shape", SHAPES)
def test_float32_vertices_match_the_exact_reference_of_their_values(shape):
    vertices, faces = _placed(shape, "unit", 3, rotate=True)
    # Rounding each coordinate on its own keeps the caps' z (and the sides' x, y) equal.
    single = vertices.astype(np.float32)
    _assert_matches(polymass.mass_properties(single, faces), single, faces)


def test_a_cavity_is_subtracted():
    """A second shell with its faces turned into the cavity removes its volume."""
    rng = np.random.default_rng(4)
    outer, outer_faces = SHAPES["star"](rng)
    inner = outer * 0.25 + 0.05  # inside: every star radius is at least 0.4
    vertices = np.vstack([outer, inner])
    faces = np.vstack([outer_faces, outer_faces[:, ::-1] + len(outer)])
    _assert_matches(polymass.mass_properties(vertices, faces), vertices, faces)


@pytest.mark.parametrize("about", ["origin", (3.0, -2.0, 0.5)])
def test_inertia_about_a_point_is_the_parallel_axis_tensor(about):
    vertices, faces = _placed("hull", "unit", 5, rotate=True)
    properties = polymass.mass_properties(vertices, faces, density=7.5, about=about)
    exact = exact_solid(vertices, faces)
    point = np.zeros(3) if about == "origin" else np.array(about)
    mass = 7.5 * exact.volume
    d = [c - float(p) for c, p in zip(exact.center_of_mass, point)]
    shifted = [
        [
            7.5 * exact.inertia[i][j]
            + mass * ((sum(x * x for x in d) if i == j else 0) - d[i] * d[j])
            for j in range(3)
        ]
        for i in range(3)
    ]
    assert_close(properties.inertia_point, shifted, RELATIVE, "inertia about the point")
    np.testing.assert_array_equal(properties.point, point)
    assert_close(properties.mass, mass, RELATIVE, "mass")


def test_a_given_mass_sets_the_density():
    vertices, faces = _placed("star", "unit", 6, rotate=False)
    properties = polymass.mass_properties(vertices, faces, mass=2.0)
    exact = exact_solid(vertices, faces)
    assert properties.mass == 2.0
    assert_close(properties.density, 2 / exact.volume, RELATIVE, "density")
    assert_close(
        properties.inertia,
        [[2 / exact.volume * x for x in row] for row in exact.inertia],
        RELATIVE,
        "inertia",
    )


@pytest.mark.parametrize("placement", PLACEMENTS)
@pytest.mark.parametrize("shape", SHAPES)
def test_error_bound_contains_the_error(shape, placement):
    vertices, faces = _placed(shape, placement, 5, rotate=True)
    p = polymass.mass_properties(vertices, faces)
    exact = exact_solid(vertices, faces)

    def error(actual, exact_values) -> float:
        expected = np.vectorize(float)(np.array(exact_values, dtype=object)).astype(np.float64)
        # The exact value is compared rounded: half an ulp of slack.
        slack = 0.5 * np.finfo(np.float64).eps * np.abs(expected)
        return float(np.max(np.abs(np.asarray(actual) - expected) - slack))

    bound = p.error_bound
    assert error(p.volume, exact.volume) <= bound.volume
    assert error(p.center_of_mass, exact.center_of_mass) <= bound.center_of_mass
    assert error(p.inertia, exact.inertia) <= bound.inertia
    assert 0 < bound.volume <= 1e-9 * p.volume, "loose, but not vacuous"
    assert 0 <= bound.principal_axes <= np.pi / 2
