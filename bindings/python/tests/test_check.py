"""check(): the full report, with locations, and welding of triangle soups."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from shapes import SHAPES, soup


def test_a_closed_solid_is_ok_and_counted(tetrahedron):
    report = polymass.check(*tetrahedron)
    assert report.ok and report.error is None and report.message == ""
    assert (report.face_count, report.used_vertex_count, report.edge_count) == (4, 4, 6)
    assert report.open_edges == 0 and report.first_open_edges == ()
    assert report.signed_volume == pytest.approx(1 / 6, rel=1e-15)
    report.raise_if_error()


def test_an_open_surface_is_located(tetrahedron):
    vertices, faces = tetrahedron
    report = polymass.check(vertices, faces[1:])
    assert report.error is polymass.OpenSurfaceError
    assert report.open_edges == 3
    # All three edges of the missing face, each as its neighbour traverses it:
    # against the missing face's direction.
    a, b, c = (int(v) for v in faces[0])
    assert set(report.first_open_edges) == {(b, a), (c, b), (a, c)}


def test_a_flipped_face_is_located(cube):
    vertices, faces = cube
    faces = [face[::-1] if k == 3 else face for k, face in enumerate(faces)]
    report = polymass.check(vertices, faces)
    assert report.error is polymass.InconsistentOrientationError
    assert report.misoriented_edges == 4
    assert len(report.first_misoriented_edges) == 4
    assert all(set(edge) <= set(faces[3]) for edge in report.first_misoriented_edges)


def test_non_planar_faces_are_counted_with_their_worst_deviation(cube):
    vertices, faces = cube
    bent = vertices.copy()
    bent[7] += 0.01  # the corner (1, 1, 1) off the planes of its three squares
    report = polymass.check(bent, faces)
    assert report.error is polymass.NonPlanarFaceError
    assert report.non_planar_faces == 3
    assert report.first_non_planar_faces == (1, 3, 5)
    assert 1e-3 < report.max_non_planarity < 1e-2
    # A looser tolerance accepts it.
    assert polymass.check(bent, faces, planarity_tolerance=0.01).ok


def test_degenerate_faces_are_harmless_and_reported(tetrahedron):
    vertices, faces = tetrahedron
    # A zero-area sliver (0, 1, 1)-style: a repeated vertex, used in both directions.
    extra = np.array([[0, 1, 0], [0, 0, 1]])
    report = polymass.check(vertices, np.vstack([faces, extra]))
    assert report.degenerate_faces == 2 and report.first_degenerate_faces == (4, 5)


def test_many_findings_list_the_lowest_eight(cube):
    vertices, faces = cube
    report = polymass.check(vertices, faces + [[0, 1]] * 10)  # faces 6 to 15 have 2 vertices
    assert report.error is polymass.FaceTooSmallError
    assert report.small_faces == 10
    assert report.first_small_faces == tuple(range(6, 14))


@pytest.mark.parametrize("shape", ["star", "hull"])
def test_welding_makes_a_triangle_soup_a_solid(shape):
    vertices, triangles = SHAPES[shape](np.random.default_rng(7))
    soup_vertices, soup_faces = soup(vertices, triangles)
    assert polymass.check(soup_vertices, soup_faces).error is polymass.OpenSurfaceError
    welded = polymass.check(soup_vertices, soup_faces, weld=True)
    assert welded.ok and welded.used_vertex_count == len(vertices)
    from_soup = polymass.mass_properties(soup_vertices, soup_faces, weld=True)
    indexed = polymass.mass_properties(vertices, triangles)
    assert from_soup.volume == pytest.approx(indexed.volume, rel=1e-14)


def test_a_weld_tolerance_joins_vertices_carrying_rounding_noise(tetrahedron):
    vertices, faces = tetrahedron
    soup_vertices, soup_faces = soup(vertices, faces)
    noisy = soup_vertices + np.random.default_rng(8).uniform(-1e-12, 1e-12, soup_vertices.shape)
    assert not polymass.check(noisy, soup_faces, weld=True).ok
    assert polymass.check(noisy, soup_faces, weld=1e-9).ok


def test_weld_is_a_boolean_or_a_float(tetrahedron):
    vertices, faces = tetrahedron
    soup_vertices, soup_faces = soup(vertices, faces)
    assert polymass.check(soup_vertices, soup_faces, weld=np.True_).ok
    assert polymass.check(soup_vertices, soup_faces, weld=0.0).ok  # a tolerance of 0: exact
    assert polymass.check(soup_vertices, soup_faces, weld=np.False_).error is (
        polymass.OpenSurfaceError
    )
    for ambiguous in (0, 1, np.int64(0)):
        with pytest.raises(TypeError, match="weld must be"):
            polymass.check(soup_vertices, soup_faces, weld=ambiguous)


@pytest.mark.parametrize("tolerance", [-1.0, 0.1, float("nan")])
def test_a_weld_tolerance_out_of_range_is_refused(tetrahedron, tolerance):
    with pytest.raises(polymass.InvalidArgumentError, match="weld_tolerance"):
        polymass.check(*tetrahedron, weld=tolerance)


def test_skip_checks_trusts_the_input_and_says_so(tetrahedron):
    vertices, faces = tetrahedron
    result = polymass.mass_properties(vertices, faces, skip_checks=True)
    assert result.warnings == (
        polymass.Warnings.UNCHECKED | polymass.Warnings.INTERSECTIONS_UNCHECKED
    )
    assert result.volume == pytest.approx(1 / 6, rel=1e-15)
    # The report says which checks ran.
    assert polymass.check(*tetrahedron).checks == (
        polymass.Checks.TOPOLOGY | polymass.Checks.SHELLS | polymass.Checks.INTERSECTIONS
    )
    assert not polymass.check(*tetrahedron, skip_checks=True).checks & polymass.Checks.TOPOLOGY
    skipped = polymass.check(*tetrahedron, skip_intersection_check=True).checks
    assert skipped == polymass.Checks.TOPOLOGY | polymass.Checks.SHELLS


def test_shells_split_as_welding_joins(cube):
    vertices, faces = cube
    apart = np.vstack([vertices, vertices + [3.0, 0.0, 0.0]])
    two = faces + [[i + 8 for i in face] for face in faces]
    assert polymass.Mesh(apart, two).shell_of_face.tolist() == [0] * 6 + [1] * 6
    triangles = np.array([[f[0], f[k], f[k + 1]] for f in faces for k in (1, 2)])
    soup_vertices, soup_faces = soup(vertices, triangles)
    unwelded = polymass.Mesh(soup_vertices, soup_faces)
    assert unwelded.error is polymass.OpenSurfaceError
    assert unwelded.shell_of_face.max() == 11  # every triangle alone
    assert polymass.Mesh(soup_vertices, soup_faces, weld=True).shell_of_face.tolist() == [0] * 12
    with pytest.raises(polymass.IndexOutOfRangeError, match="face 1"):
        _ = polymass.Mesh(vertices, [faces[0], [0, 1, 99]]).shell_of_face
