"""One analysis per mesh (`Mesh`), options per call (`Options`), welding on its own (`weld`)."""

from __future__ import annotations

import gc

import numpy as np
import pytest

import polymass
from polymass._arrays import mesh_description
from shapes import SHAPES, soup


def _same(a: polymass.MassProperties, b: polymass.MassProperties) -> None:
    for field in (
        "volume",
        "mass",
        "density",
        "surface_area",
        "center_of_mass",
        "inertia",
        "inertia_origin",
        "inertia_point",
        "principal_moments",
        "principal_axes",
    ):
        assert np.array_equal(getattr(a, field), getattr(b, field), equal_nan=True), field
    assert (a.warnings, a.error_bound, a.provenance) == (b.warnings, b.error_bound, b.provenance)


@pytest.mark.parametrize("shape", sorted(SHAPES))
def test_a_mesh_answers_as_the_one_call_path_bit_for_bit(shape):
    vertices, faces = SHAPES[shape](np.random.default_rng(41))
    vertices = vertices + [1e5, -2e5, 3e5]
    mesh = polymass.Mesh(vertices, faces)
    assert mesh.ok and mesh.status == 0 and mesh.message == "" and mesh.error is None
    mesh.raise_if_error()
    for body in ({}, {"density": 2700.0}, {"mass": 3.5, "about": "origin"}, {"about": (1, 2, 3)}):
        _same(mesh.mass_properties(**body), polymass.mass_properties(vertices, faces, **body))
    assert mesh.diagnostics == polymass.check(vertices, faces)
    assert mesh.provenance == polymass.Provenance()
    whole = polymass.moments(vertices, faces)
    assert mesh.moments.volume == whole.volume
    assert np.array_equal(mesh.moments.second, whole.second)
    _same(mesh.moments.mass_properties(), whole.mass_properties())
    assert [(s.kind, s.face_count) for s in mesh.shells] == [("solid", len(faces))]
    assert mesh.shell_of_face.tolist() == [0] * len(faces)
    assert "ok" in repr(mesh)


def test_a_mesh_keeps_nothing_of_the_arrays(tetrahedron):
    vertices, faces = (array.copy() for array in tetrahedron)
    mesh = polymass.Mesh(vertices, faces)
    before = mesh.mass_properties()
    vertices[:] = np.nan
    faces[:] = 99
    del vertices, faces
    gc.collect()
    _same(mesh.mass_properties(), before)
    assert before.volume == pytest.approx(1 / 6, rel=1e-15)


def test_a_refused_mesh_says_why_and_answers_nothing(tetrahedron):
    vertices, faces = tetrahedron
    mesh = polymass.Mesh(vertices, faces[1:])
    assert mesh.error is polymass.OpenSurfaceError and not mesh.ok
    assert mesh.message and "edge" in mesh.message
    assert mesh.diagnostics.open_edges == 3
    assert mesh.diagnostics.message == mesh.message
    assert "OpenSurfaceError" in repr(mesh)
    for question in (
        lambda: mesh.mass_properties(),
        lambda: mesh.moments,
        lambda: mesh.provenance,
        mesh.raise_if_error,
    ):
        with pytest.raises(polymass.OpenSurfaceError) as raised:
            question()
        assert raised.value.message == mesh.message
    # Unreadable faces: no shells to number.
    unreadable = polymass.Mesh(np.where(vertices == 1, np.inf, vertices), faces)
    assert unreadable.error is polymass.NonFiniteError
    with pytest.raises(polymass.NonFiniteError):
        _ = unreadable.shell_of_face


def test_a_call_that_describes_no_analysis_raises_at_once(tetrahedron):
    vertices, faces = tetrahedron
    with pytest.raises(polymass.InvalidArgumentError, match="weld_tolerance"):
        polymass.Mesh(vertices, faces, weld=0.5)
    with pytest.raises(polymass.InvalidArgumentError):
        polymass.Mesh(vertices, faces, modes="shell", shell_thickness=-1.0)


def test_options_are_one_value_and_keywords_replace_its_fields(tetrahedron):
    vertices, faces = tetrahedron
    reversed_faces = faces[:, ::-1]
    turned = polymass.Options(accept_inverted=True)
    assert turned.modes == ("solid",) and turned.weld is False
    assert polymass.mass_properties(vertices, reversed_faces, options=turned).warnings == (
        polymass.Warnings.INVERTED
    )
    both = polymass.mass_properties(
        vertices, reversed_faces, options=turned, skip_intersection_check=True
    )
    assert both.warnings == polymass.Warnings.INVERTED | polymass.Warnings.INTERSECTIONS_UNCHECKED
    with pytest.raises(polymass.InvertedError):
        polymass.mass_properties(vertices, reversed_faces, options=turned, accept_inverted=False)
    assert turned.accept_inverted  # options are never changed by a call
    with pytest.raises(AttributeError):
        turned.weld = True  # type: ignore[misc]
    assert polymass.Options(modes="solid,repair").modes == ("solid", "repair")
    assert polymass.Options(modes=["hull"]) == polymass.Options(modes=("hull",))


def test_unknown_options_and_wrong_types_are_refused(tetrahedron):
    with pytest.raises(TypeError, match="unknown option fallback; the options are weld"):
        polymass.mass_properties(*tetrahedron, fallback=["repair"])
    with pytest.raises(TypeError, match="unknown option threds"):
        polymass.Mesh(*tetrahedron, threds=2)
    with pytest.raises(TypeError, match=r"options must be a polymass\.Options"):
        polymass.check(*tetrahedron, options={"weld": True})
    with pytest.raises(TypeError, match="weld must be"):
        polymass.Options(weld=1)


def test_every_analysing_call_takes_the_same_options(tetrahedron):
    vertices, faces = tetrahedron
    soup_vertices, soup_faces = soup(vertices, faces)
    welded = polymass.Options(weld=True)
    assert polymass.check(soup_vertices, soup_faces, options=welded).ok
    assert polymass.Mesh(soup_vertices, soup_faces, options=welded).ok
    assert polymass.mass_properties(soup_vertices, soup_faces, options=welded).volume == (
        pytest.approx(1 / 6, rel=1e-15)
    )
    assert polymass.moments(soup_vertices, soup_faces, options=welded).volume == (
        pytest.approx(1 / 6, rel=1e-15)
    )
    [result] = polymass.batch([(soup_vertices, soup_faces)], options=welded)
    assert result.volume == pytest.approx(1 / 6, rel=1e-15)
    [refused] = polymass.batch([(soup_vertices, soup_faces)])
    assert isinstance(refused, polymass.OpenSurfaceError)


def test_batch_items_carry_their_provenance():
    rng = np.random.default_rng(42)
    vertices, faces = SHAPES["hull"](rng)
    flipped = np.asarray(faces).copy()
    flipped[0] = flipped[0][::-1]
    results = polymass.batch([(vertices, faces), (vertices, flipped)], modes=("solid", "repair"))
    assert [r.provenance.mode for r in results] == ["solid", "repaired"]
    assert results[1].provenance.repairs["reoriented_faces"].first == (0,)
    single = polymass.mass_properties(vertices, flipped, modes=("solid", "repair"))
    _same(results[1], single)


def test_weld_numbers_a_triangle_soup_by_its_positions():
    vertices, triangles = SHAPES["star"](np.random.default_rng(43))
    soup_vertices, soup_faces = soup(vertices, triangles)
    welded = polymass.weld(soup_vertices)
    assert welded.distinct_count == len(vertices)
    assert welded.vertex_of.dtype == np.uint32 and not welded.vertex_of.flags.writeable
    first = welded.vertex_of
    assert np.all(first <= np.arange(len(soup_vertices)))
    assert np.array_equal(soup_vertices[first], soup_vertices)
    indexed = first[soup_faces]
    assert polymass.check(soup_vertices, indexed).ok
    _same(
        polymass.mass_properties(soup_vertices, indexed),
        polymass.mass_properties(soup_vertices, soup_faces, weld=True),
    )


def test_weld_with_a_tolerance_joins_rounding_noise(tetrahedron):
    vertices, faces = tetrahedron
    soup_vertices, _ = soup(vertices, faces)
    noisy = soup_vertices + np.random.default_rng(44).uniform(-1e-12, 1e-12, soup_vertices.shape)
    assert polymass.weld(noisy).distinct_count == len(soup_vertices)
    assert polymass.weld(noisy, tolerance=1e-9).distinct_count == 4
    # Read in place through a stride, as a mesh's vertices are.
    interleaved = np.zeros((len(noisy), 6), dtype=np.float32)
    interleaved[:, :3] = soup_vertices
    assert polymass.weld(interleaved[:, :3]).distinct_count == 4
    with pytest.raises(polymass.InvalidArgumentError):
        polymass.weld(noisy, tolerance=0.5)
    with pytest.raises(polymass.NonFiniteError):
        polymass.weld(np.vstack([noisy, [np.nan, 0, 0]]), tolerance=1e-9)


def test_the_buffers_handed_to_the_library_hold_the_arrays(tetrahedron):
    """ffi.from_buffer keeps the arrays the description points into alive, even
    the ones the binding made (a conversion of int64 indices, a strided view)."""
    vertices, faces = tetrahedron
    wide = np.zeros((len(vertices), 5))
    wide[:, :3] = vertices
    description = mesh_description(wide[:, :3], faces.astype(np.int64), None)
    del wide
    gc.collect()
    assert len(description.buffers) == 2
    positions = polymass._library.ffi.cast("double *", description.desc.positions)
    assert [positions[5 * 3 + k] for k in range(3)] == [0.0, 0.0, 1.0]


def test_the_inertia_about_a_point_that_has_none_is_refused(tetrahedron):
    mesh = polymass.Mesh(*tetrahedron)
    with pytest.raises(polymass.InvalidArgumentError, match=r"about the point \[nan, 0.0, 0.0\]"):
        mesh.mass_properties(about=(np.nan, 0.0, 0.0))
    with pytest.raises(polymass.ResultOutOfRangeError, match="about the point"):
        mesh.mass_properties(about=(1e300, 0.0, 0.0))
    far = mesh.mass_properties(about=(1e6, 0.0, 0.0))
    dx, _, dz = far.center_of_mass - far.point
    expected = far.inertia[1, 1] + far.mass * (dx * dx + dz * dz)  # the parallel-axis theorem
    assert far.inertia_point[1, 1] == pytest.approx(expected, rel=1e-15)
