"""Every status the library reports arrives as its own exception with the library's message."""

from __future__ import annotations

import re

import numpy as np
import pytest

import polymass
from polymass import _header
from polymass.errors import error_class


def _open_tetrahedron(tetrahedron):
    vertices, faces = tetrahedron
    return vertices, faces[:3]


def _two_tetrahedra_sharing_an_edge(tetrahedron):
    vertices, faces = tetrahedron
    all_vertices = np.vstack([vertices, [[0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]])
    # The corner tetrahedron turned half a turn about the x axis (vertex 2 -> 4, 3 -> 5):
    # it touches the first along edge (0, 1) only.
    other = np.array([[0, 4, 1], [0, 1, 5], [0, 5, 4], [1, 4, 5]], dtype=np.uint32)
    return all_vertices, np.vstack([faces, other])


def _flipped_face(tetrahedron):
    vertices, faces = tetrahedron
    flipped = faces.copy()
    flipped[1] = flipped[1][::-1]
    return vertices, flipped


def _bent_cube(cube):
    vertices, faces = cube
    bent = vertices.copy()
    bent[7] += 0.01  # the corner (1, 1, 1) off the planes of its three squares
    return bent, faces


CASES = [
    (
        polymass.NonFiniteError,
        "vertex 2",
        lambda t, c: (np.where([[0], [0], [1], [0]], np.nan, t[0]), t[1]),
    ),
    (polymass.IndexOutOfRangeError, "9", lambda t, c: (t[0], np.where(t[1] == 3, 9, t[1]))),
    (polymass.FaceTooSmallError, "face 1 has 2 vertices", lambda t, c: (t[0], [[0, 2, 1], [0, 1]])),
    (polymass.OpenSurfaceError, "used by one face only", lambda t, c: _open_tetrahedron(t)),
    (polymass.NonManifoldError, "edge (0, 1)", lambda t, c: _two_tetrahedra_sharing_an_edge(t)),
    (polymass.InconsistentOrientationError, "edge", lambda t, c: _flipped_face(t)),
    (polymass.NonPlanarFaceError, "face", lambda t, c: _bent_cube(c)),
    (polymass.InvertedError, "", lambda t, c: (t[0], t[1][:, ::-1])),
    (polymass.ZeroVolumeError, "", lambda t, c: (t[0], [[0, 1, 2], [0, 2, 1]])),
    (polymass.ResultOutOfRangeError, "", lambda t, c: (t[0] * 1e300, t[1])),
]


@pytest.mark.parametrize(("error", "where", "make"), CASES, ids=[c[0].__name__ for c in CASES])
def test_each_mesh_error_is_its_own_exception_with_the_message(
    tetrahedron, cube, error, where, make
):
    vertices, faces = make(tetrahedron, cube)
    with pytest.raises(error) as raised:
        polymass.mass_properties(vertices, faces)
    exception = raised.value
    assert isinstance(exception, polymass.Error)
    assert exception.status == error.status
    assert exception.message, "the library's message is carried"
    assert where in exception.message
    assert str(exception) == f"{exception.status_name}: {exception.message}"
    # check() reports the same status and message instead of raising.
    report = polymass.check(vertices, faces)
    assert (report.status, report.message) == (exception.status, exception.message)
    assert report.error is error


def test_invalid_argument_from_the_library(tetrahedron):
    with pytest.raises(polymass.InvalidArgumentError, match="density") as raised:
        polymass.mass_properties(*tetrahedron, density=-1.0)
    assert isinstance(raised.value, ValueError)


def test_zero_area_polygon():
    with pytest.raises(polymass.ZeroAreaError) as raised:
        polymass.polygon_properties([[0, 0], [1, 1], [2, 2]])
    assert raised.value.message


def test_non_manifold_edges_touching_solids_are_accepted_on_request(tetrahedron):
    vertices, faces = _two_tetrahedra_sharing_an_edge(tetrahedron)
    both = polymass.mass_properties(vertices, faces, accept_non_manifold=True)
    assert both.warnings & polymass.Warnings.NON_MANIFOLD
    assert both.volume == pytest.approx(2 / 6, rel=1e-15)


def test_every_status_of_the_header_has_its_exception_class():
    statuses = {
        value for name, value in vars(_header).items() if name.startswith("POLYMASS_ERROR_")
    }
    for status in statuses:
        cls = error_class(status)
        assert cls is not polymass.Error and cls.status == status
        assert cls.__name__ in polymass.__all__
    assert error_class(9999) is polymass.Error


def test_topology_errors_share_a_base():
    for cls in (
        polymass.OpenSurfaceError,
        polymass.NonManifoldError,
        polymass.InconsistentOrientationError,
        polymass.NonPlanarFaceError,
    ):
        assert issubclass(cls, polymass.TopologyError)


def test_raise_if_error_raises_what_mass_properties_would(tetrahedron):
    report = polymass.check(*_open_tetrahedron(tetrahedron))
    with pytest.raises(polymass.OpenSurfaceError, match=re.escape(report.message)):
        report.raise_if_error()
