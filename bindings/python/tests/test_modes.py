"""The modes: repair, shell, hull and chains of them, with their provenance."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from shapes import sphere_triangulation


@pytest.fixture
def sphere():
    return sphere_triangulation(200)


def _within(result, exact):
    """The answer lies within its error bound of the exact one."""
    bound = result.error_bound
    assert abs(result.volume - exact.volume) <= bound.volume
    assert np.all(np.abs(result.center_of_mass - exact.center_of_mass) <= bound.center_of_mass)
    assert np.all(np.abs(result.inertia - exact.inertia) <= bound.inertia)


def test_a_hole_is_capped_within_its_bound(sphere):
    vertices, triangles = sphere
    exact = polymass.mass_properties(vertices, triangles)
    centroids = vertices[triangles].mean(axis=1)
    kept = triangles[np.linalg.norm(centroids - [0, 0, 1], axis=1) > 0.4]
    with pytest.raises(polymass.OpenSurfaceError):
        polymass.mass_properties(vertices, kept)
    repaired = polymass.mass_properties(vertices, kept, modes="repair")
    assert repaired.provenance.mode == "repaired"
    assert repaired.provenance.repairs["holes"].count == 1
    assert 0 < repaired.provenance.cap_area_fraction < 0.1
    assert repaired.provenance.approximation_bound["volume"] > 0
    assert polymass.Warnings.REPAIRED in repaired.warnings
    _within(repaired, exact)


def test_flipped_faces_are_turned_exactly(sphere):
    vertices, triangles = sphere
    exact = polymass.mass_properties(vertices, triangles)
    flipped = triangles.copy()
    flipped[::5] = flipped[::5, ::-1]
    repaired = polymass.mass_properties(vertices, flipped, modes="repair")
    assert repaired.provenance.repairs["reoriented_faces"].count == len(flipped[::5])
    assert repaired.provenance.repairs["reoriented_faces"].first[:2] == (0, 5)
    assert repaired.provenance.approximation_bound["volume"] == 0
    assert repaired.volume == pytest.approx(exact.volume, rel=1e-13)


def test_a_valid_solid_is_answered_as_without_modes(sphere):
    vertices, triangles = sphere
    exact = polymass.mass_properties(vertices, triangles)
    for keywords in (
        {"modes": "repair"},
        {"modes": ("solid", "repair", "hull")},
        {"modes": "solid,repair"},
    ):
        result = polymass.mass_properties(vertices, triangles, **keywords)
        assert result.provenance.mode == "solid"
        assert result.volume == exact.volume
        assert np.array_equal(result.inertia, exact.inertia)
        assert result.error_bound == exact.error_bound


def test_the_hull_answers_what_repair_cannot(tetrahedron):
    vertices, faces = tetrahedron
    # A fin on an edge: used by three faces, two one way and one the other.
    fin_vertices = np.vstack([vertices, [[2.0, 2.0, -1.0]]])
    fin_faces = np.vstack([faces, [[faces[0][0], faces[0][1], 4]]])
    with pytest.raises(polymass.OpenSurfaceError, match="repair: edge"):
        polymass.mass_properties(fin_vertices, fin_faces, modes=["repair"])
    result = polymass.mass_properties(fin_vertices, fin_faces, modes=["solid", "repair", "hull"])
    assert result.provenance.mode == "hull"
    assert result.provenance.hull_vertex_count == 5
    assert result.volume == pytest.approx(result.provenance.hull_volume)
    assert polymass.Warnings.HULL in result.warnings


def test_a_shell_is_a_thin_wall():
    # An open box (no lid) of side 2: area 20.
    vertices = np.array(
        [[x, y, z] for z in (0.0, 2.0) for y in (0.0, 2.0) for x in (0.0, 2.0)], dtype=float
    )
    quads = [[0, 2, 3, 1], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6]]
    result = polymass.mass_properties(
        vertices, quads, modes="shell", shell_thickness=0.01, density=7850.0
    )
    assert result.provenance.mode == "shell"
    assert result.provenance.shell_area == pytest.approx(20.0, rel=1e-14)
    assert result.mass == pytest.approx(7850.0 * 0.01 * 20.0, rel=1e-14)


@pytest.mark.parametrize(
    "keywords",
    [
        {"modes": ["repair", "bogus"]},
        {"modes": ["shell"]},
        {"shell_thickness": 0.01},
        {"modes": ()},
        {"modes": ["solid", "repair", "shell", "hull", "solid"], "shell_thickness": 0.01},
    ],
)
def test_contradictory_modes_are_refused(tetrahedron, keywords):
    with pytest.raises(ValueError, match="mode"):
        polymass.mass_properties(*tetrahedron, **keywords)
    with pytest.raises(ValueError, match="mode"):
        polymass.Options(**keywords)


def test_a_mesh_tells_which_mode_answered(sphere):
    vertices, triangles = sphere
    flipped = triangles.copy()
    flipped[::5] = flipped[::5, ::-1]
    mesh = polymass.Mesh(vertices, flipped, modes=("solid", "repair"))
    # It answered; what is wrong with the surface as given is still said.
    assert mesh.ok and mesh.error is None
    assert mesh.diagnostics.solid_status == polymass.InconsistentOrientationError.status
    assert mesh.message and mesh.message == polymass.Mesh(vertices, flipped).message
    assert mesh.diagnostics.misoriented_edges > 0
    assert mesh.provenance.mode == "repaired"
    assert mesh.mass_properties().provenance == mesh.provenance
    one_call = polymass.mass_properties(vertices, flipped, modes=("solid", "repair"))
    assert one_call.volume == mesh.mass_properties().volume
