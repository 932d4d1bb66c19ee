"""Agreement with trimesh where it is accurate, and the exact reference where it is not.

trimesh integrates about the origin, so a part far from it loses digits to
cancellation; near the origin both are accurate and must agree closely.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

import polymass
from exact import assert_close, exact_solid
from shapes import SHAPES, random_rotation, torus


def _triangles(vertices, faces) -> np.ndarray:
    """Fan triangles of polygon faces (trimesh takes triangles only)."""
    return np.array([[f[0], f[k], f[k + 1]] for f in faces for k in range(1, len(f) - 1)])


def _both(vertices, faces):
    triangles = _triangles(vertices, faces)
    # A fan over a non-convex cap overlaps itself in the cap's plane, cancelling; rotated, the
    # overlaps leave the plane by a rounding error and cross, and the intersection check (exact)
    # refuses the surface. The integrals are compared here: the check is skipped.
    ours = polymass.mass_properties(vertices, triangles, density=3.0, skip_intersection_check=True)
    theirs = trimesh.Trimesh(vertices, triangles, process=False)
    theirs.density = 3.0
    return ours, theirs


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("seed", [11, 12, 13])
def test_agrees_with_trimesh_near_the_origin(shape, seed):
    rng = np.random.default_rng(seed)
    vertices, faces = SHAPES[shape](rng)
    ours, theirs = _both(vertices @ random_rotation(rng).T, faces)
    relative = 1e-10
    assert ours.volume == pytest.approx(theirs.volume, rel=relative)
    assert ours.mass == pytest.approx(theirs.mass, rel=relative)
    assert ours.surface_area == pytest.approx(theirs.area, rel=relative)
    np.testing.assert_allclose(ours.center_of_mass, theirs.center_mass, rtol=0, atol=relative)
    # Same sign convention: negated products of inertia off the diagonal.
    scale = np.max(np.abs(ours.inertia))
    np.testing.assert_allclose(ours.inertia, theirs.moment_inertia, rtol=0, atol=relative * scale)
    np.testing.assert_allclose(
        ours.principal_moments, np.sort(theirs.principal_inertia_components), rtol=relative
    )


def test_agrees_with_trimesh_on_a_fine_torus():
    vertices, faces = torus(2.0, 0.5, 200, 100)
    ours, theirs = _both(vertices, faces)
    assert ours.volume == pytest.approx(theirs.volume, rel=1e-10)
    scale = np.max(np.abs(ours.inertia))
    np.testing.assert_allclose(ours.inertia, theirs.moment_inertia, rtol=0, atol=1e-10 * scale)


@pytest.mark.parametrize("offset", [1e6, 1e7, 1e8])
@pytest.mark.parametrize("shape", SHAPES)
def test_far_from_the_origin_the_exact_reference_decides(shape, offset):
    """Where integrating about the origin (as trimesh does) loses digits, ours must not."""
    rng = np.random.default_rng(21)
    vertices, faces = SHAPES[shape](rng)
    vertices = vertices + offset
    ours = polymass.mass_properties(vertices, faces)
    exact = exact_solid(vertices, faces)
    assert_close(ours.inertia, exact.inertia, 1e-12, "inertia about the centre of mass")
    assert_close(ours.center_of_mass, exact.center_of_mass, 1e-12, "centre of mass")
    assert_close(ours.volume, exact.volume, 1e-12, "volume")
