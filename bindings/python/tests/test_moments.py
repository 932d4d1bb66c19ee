"""Moments that compose, against the exact rational reference: parts added, moved
(also far from the origin), mirrored and scaled; weighted parts; face ranges."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import polymass
from exact import assert_close, exact_solid
from shapes import SHAPES, random_rotation

# Two computations that should agree to the last digits.
SUM_RELATIVE = 1e-15
RELATIVE = 1e-12


def _faces_list(faces):
    return [list(map(int, face)) for face in faces]


def _solid(shape: str, seed: int, offset):
    vertices, faces = SHAPES[shape](np.random.default_rng(seed))
    return vertices + np.asarray(offset, dtype=np.float64), _faces_list(faces)


def _both(a, b):
    """One mesh holding the two solids."""
    (va, fa), (vb, fb) = a, b
    return np.vstack([va, vb]), fa + [[i + len(va) for i in face] for face in fb]


@pytest.mark.parametrize("offset", [(5.0, 0.0, 0.0), (1e6, -1e6, 2e6), (1e8, 0.0, -1e8)])
@pytest.mark.parametrize("shape", SHAPES)
def test_disjoint_parts_add_up_to_the_mesh_holding_both(shape, offset):
    a = _solid(shape, 1, (0.0, 0.0, 0.0))
    b = _solid(shape, 2, offset)
    total = polymass.moments(*a) + polymass.moments(*b)
    exact = exact_solid(*_both(a, b))
    p = total.mass_properties()
    assert_close(p.volume, exact.volume, SUM_RELATIVE, "volume")
    assert_close(p.center_of_mass, exact.center_of_mass, SUM_RELATIVE, "centre of mass")
    assert_close(p.inertia, exact.inertia, SUM_RELATIVE, "inertia")


def _moved_exact(exact, rotation, translation):
    """The exact values of the solid moved by x -> R x + t, in rationals."""
    r = [[Fraction(float(x)) for x in row] for row in rotation]
    t = [Fraction(float(x)) for x in translation]
    com = [sum(r[i][k] * exact.center_of_mass[k] for k in range(3)) + t[i] for i in range(3)]
    ri = [
        [sum(r[i][k] * exact.inertia[k][j] for k in range(3)) for j in range(3)] for i in range(3)
    ]
    inertia = [[sum(ri[i][k] * r[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
    return com, inertia


@pytest.mark.parametrize("translation", [(0.0, 0.0, 0.0), (1e6, 2e6, -3e6), (1e8, -1e8, 1e8)])
@pytest.mark.parametrize("mirror", [False, True])
def test_moved_moments_are_the_moved_solid(translation, mirror):
    vertices, faces = _solid("star", 3, (0.0, 0.0, 0.0))
    rotation = random_rotation(np.random.default_rng(4))
    if mirror:
        rotation = rotation @ np.diag([1.0, 1.0, -1.0])
    moved = polymass.moments(vertices, faces).transformed(
        rotation=rotation, translation=translation
    )
    exact = exact_solid(vertices, faces)
    com, inertia = _moved_exact(exact, rotation, translation)
    p = moved.mass_properties()
    assert_close(p.volume, exact.volume, RELATIVE, "volume (a mirror keeps it positive)")
    assert_close(p.center_of_mass, com, SUM_RELATIVE, "centre of mass")
    assert_close(p.inertia, inertia, RELATIVE, "inertia")


def test_quaternion_and_matrix_move_alike():
    vertices, faces = _solid("hull", 5, (0.0, 0.0, 0.0))
    q = np.array([0.5, 0.5, -0.5, 0.5])
    m = polymass.moments(vertices, faces)
    by_quaternion = m.transformed(rotation=q, translation=(1, 2, 3)).mass_properties()
    matrix = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]])  # the same rotation
    by_matrix = m.transformed(rotation=matrix, translation=(1, 2, 3)).mass_properties()
    np.testing.assert_allclose(by_quaternion.inertia, by_matrix.inertia, rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(by_quaternion.center_of_mass, by_matrix.center_of_mass, rtol=1e-15)


def test_scaled_moments_are_the_scaled_mesh():
    vertices, faces = _solid("extrusion", 6, (1.0, -2.0, 0.5))
    factors = np.array([2.0, -0.5, 4.0])  # a per-axis scale with a mirror: exact on the mesh
    scaled = polymass.moments(vertices, faces).scaled(factors).mass_properties()
    mesh = polymass.mass_properties(vertices * factors, faces, accept_inverted=True)
    assert_close(scaled.volume, mesh.volume, RELATIVE, "volume")
    assert_close(scaled.center_of_mass, mesh.center_of_mass, RELATIVE, "centre of mass")
    assert_close(scaled.inertia, mesh.inertia, RELATIVE, "inertia")
    uniform = polymass.moments(vertices, faces).scaled(1e-3).mass_properties()
    assert_close(uniform.volume, mesh.volume / 4.0 * 1e-9, RELATIVE, "volume in mm -> m")


def test_weighted_parts_keep_their_densities():
    a = _solid("hull", 7, (0.0, 0.0, 0.0))
    b = _solid("star", 8, (4.0, 0.0, 0.0))
    total = polymass.moments(*a).weighted(density=2700.0) + polymass.moments(*b).weighted(mass=3.0)
    pa = polymass.mass_properties(*a, density=2700.0)
    pb = polymass.mass_properties(*b, mass=3.0)
    p = total.mass_properties(about="origin")
    mass = pa.mass + pb.mass
    assert_close(p.mass, mass, SUM_RELATIVE, "mass")
    assert_close(p.volume, pa.volume + pb.volume, SUM_RELATIVE, "volume")
    assert_close(p.inertia_origin, pa.inertia_origin + pb.inertia_origin, RELATIVE, "inertia")
    com = (pa.mass * pa.center_of_mass + pb.mass * pb.center_of_mass) / mass
    assert_close(p.center_of_mass, com, RELATIVE, "centre of mass")
    assert p.density == pytest.approx(mass / p.volume, rel=1e-15)
    assert np.isnan(p.surface_area)
    again = total.mass_properties(density=1.0)
    assert again.mass == pytest.approx(p.volume, rel=1e-15)


def test_bore_removed_from_block():
    block = np.array([[x, y, z] for z in (0, 4) for y in (0, 2) for x in (0, 2)], dtype=float)
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    bore = block * [0.5, 0.5, 1.0] + [0.5, 0.5, 0.0]  # a 1 x 1 x 4 bar through it
    difference = polymass.moments(block, quads) - polymass.moments(bore, quads)
    p = difference.mass_properties()
    assert p.volume == pytest.approx(12.0, rel=1e-15)
    # A square tube of side 2 with a square hole of side 1, length 4, along z.
    izz = (16.0 * (4 + 4) - 4.0 * (1 + 1)) / 12.0
    assert p.inertia[2, 2] == pytest.approx(izz, rel=1e-14)
    with pytest.raises(polymass.ZeroVolumeError):
        (polymass.moments(bore, quads) - polymass.moments(block, quads)).mass_properties()


def test_face_ranges_add_up_to_the_surface():
    vertices, faces = _solid("star", 9, (1e6, 0.0, 0.0))
    whole = polymass.moments(vertices, faces)
    reference = whole.reference
    count = len(faces)
    ranges = [
        polymass.moments(
            vertices, faces, face_range=(first, min(50, count - first)), reference=reference
        )
        for first in range(0, count, 50)
    ]
    assert all(part.partial for part in ranges)
    total = sum(ranges[1:], ranges[0])
    with pytest.raises(polymass.InvalidArgumentError, match="PARTIAL"):
        total.mass_properties()
    a, b = whole.mass_properties(), total.completed().mass_properties()
    assert_close(b.volume, a.volume, SUM_RELATIVE, "volume")
    assert_close(b.inertia, a.inertia, SUM_RELATIVE, "inertia")
    with pytest.raises(ValueError, match="reference"):
        polymass.moments(vertices, faces, face_range=(0, 10))


def test_sum_of_parts_and_repr():
    parts = [polymass.moments(*_solid("hull", seed, (3.0 * seed, 0.0, 0.0))) for seed in (1, 2, 3)]
    total = sum(parts)
    assert isinstance(total, polymass.Moments)
    assert total.volume == pytest.approx(sum(part.volume for part in parts), rel=1e-15)
    assert "Moments(volume=" in repr(total)
    assert total.second.shape == (3, 3) and np.allclose(total.second, total.second.T)
