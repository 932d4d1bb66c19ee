"""What arrays are accepted, which are read in place, and what is converted or refused."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from polymass._arrays import mesh_description


def _address(array: np.ndarray) -> int:
    return array.__array_interface__["data"][0]


def _seen_by_library(description) -> int:
    return int(polymass._library.ffi.cast("uintptr_t", description.desc.positions))


def _reference(tetrahedron):
    return polymass.mass_properties(*tetrahedron)


def _same(a: polymass.MassProperties, b: polymass.MassProperties) -> None:
    assert a.volume == b.volume
    np.testing.assert_array_equal(a.inertia, b.inertia)
    np.testing.assert_array_equal(a.center_of_mass, b.center_of_mass)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_a_strided_view_is_read_in_place(tetrahedron, dtype):
    vertices, faces = tetrahedron
    interleaved = np.zeros((len(vertices), 8), dtype=dtype)  # position, normal, uv
    interleaved[:, :3] = vertices
    interleaved[:, 3:] = 99.0  # not positions: must not be read as such
    view = interleaved[:, :3]
    description = mesh_description(view, faces, None)
    assert _seen_by_library(description) == _address(view)
    assert description.desc.position_stride == 8 * interleaved.itemsize
    _same(polymass.mass_properties(view, faces), _reference(tetrahedron))


def test_a_view_of_every_other_row_is_read_in_place(tetrahedron):
    vertices, faces = tetrahedron
    spaced = np.full((2 * len(vertices), 3), np.nan)
    spaced[::2] = vertices
    description = mesh_description(spaced[::2], faces, None)
    assert _seen_by_library(description) == _address(spaced)
    _same(polymass.mass_properties(spaced[::2], faces), _reference(tetrahedron))


def test_rows_overlapping_in_memory_are_copied():
    # A sliding window over (0, 0, 0, 1, 0, 0): rows (0,0,0), (0,0,1), (0,1,0),
    # (1,0,0) share memory (a row stride of one coordinate). The library wants
    # rows that do not overlap; the binding copies them.
    window = np.lib.stride_tricks.sliding_window_view(np.array([0.0, 0, 0, 1, 0, 0]), 3)
    assert window.strides == (8, 8)
    faces = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    description = mesh_description(window, faces, None)
    assert description.vertices.strides == (24, 8)
    assert polymass.mass_properties(window, faces).volume == pytest.approx(1 / 6, rel=1e-15)


def test_face_sizes_of_triangles_must_account_for_every_index(tetrahedron):
    vertices, faces = tetrahedron
    flat = np.asarray(faces).ravel()
    with pytest.raises(polymass.InvalidArgumentError, match="add up to 9 indices"):
        polymass.mass_properties(vertices, flat, face_sizes=[3, 3, 3])


@pytest.mark.parametrize(
    "layout",
    [
        pytest.param(lambda v: np.asfortranarray(v), id="column-major"),
        pytest.param(lambda v: np.ascontiguousarray(v[::-1])[::-1], id="negative-row-stride"),
        pytest.param(lambda v: v.astype(">f8"), id="big-endian"),
        pytest.param(lambda v: v.astype(np.float16), id="float16"),
        pytest.param(lambda v: v.astype(np.int64), id="int64"),
        pytest.param(lambda v: v.tolist(), id="list"),
    ],
)
def test_other_vertex_layouts_give_the_same_result(tetrahedron, layout):
    vertices, faces = tetrahedron
    _same(polymass.mass_properties(layout(vertices), faces), _reference(tetrahedron))


@pytest.mark.parametrize("dtype", [np.uint32, np.uint16, np.int32])
def test_these_index_types_are_read_in_place(tetrahedron, dtype):
    vertices, faces = tetrahedron
    indices = faces.astype(dtype)
    description = mesh_description(vertices, indices, None)
    assert np.shares_memory(description.indices, indices)
    _same(polymass.mass_properties(vertices, indices), _reference(tetrahedron))


@pytest.mark.parametrize("dtype", [np.int64, np.uint64, np.int16, np.uint8, ">u4"])
def test_other_index_types_are_converted(tetrahedron, dtype):
    vertices, faces = tetrahedron
    _same(polymass.mass_properties(vertices, faces.astype(dtype)), _reference(tetrahedron))


@pytest.mark.parametrize("bad", [-1, 2**32, 2**40])
def test_int64_indices_out_of_uint32_range_are_refused_naming_the_face(tetrahedron, bad):
    vertices, faces = tetrahedron
    indices = faces.astype(np.int64)
    indices[2, 1] = bad
    with pytest.raises(polymass.IndexOutOfRangeError, match=f"face 2 refers to vertex {bad}"):
        polymass.mass_properties(vertices, indices)


def test_an_index_past_the_vertices_is_reported_by_the_library(tetrahedron):
    vertices, faces = tetrahedron
    indices = faces.copy()
    indices[3, 0] = 7
    with pytest.raises(polymass.IndexOutOfRangeError, match="7"):
        polymass.mass_properties(vertices, indices)


def test_polygon_faces_in_every_form_agree(cube):
    vertices, faces = cube
    as_lists = polymass.mass_properties(vertices, faces)
    as_table = polymass.mass_properties(vertices, np.array(faces))
    flat = polymass.mass_properties(
        vertices, np.concatenate(faces), face_sizes=[len(face) for face in faces]
    )
    mixed = [faces[0], *[face for face in faces[1:]]]
    for other in (as_table, flat, polymass.mass_properties(vertices, mixed)):
        _same(other, as_lists)
    assert as_lists.volume == 1.0
    np.testing.assert_array_equal(as_lists.center_of_mass, [0.5, 0.5, 0.5])


def test_mixed_triangles_and_polygons(cube):
    vertices, faces = cube
    # Split the z = 1 square into two triangles.
    split = [faces[0], [4, 5, 7], [4, 7, 6], *faces[2:]]
    _same(polymass.mass_properties(vertices, split), polymass.mass_properties(vertices, faces))


@pytest.mark.parametrize(
    ("vertices", "faces", "error", "message"),
    [
        (np.zeros((4, 2)), [[0, 1, 2]], ValueError, r"shape \(n, 3\)"),
        (np.zeros(12), [[0, 1, 2]], ValueError, r"shape \(n, 3\)"),
        (np.zeros((4, 3), dtype=complex), [[0, 1, 2]], TypeError, "complex"),
        (np.zeros((4, 3), dtype=np.longdouble), [[0, 1, 2]], TypeError, "float"),
        (np.array([[2**60, 0, 0]] * 4), [[0, 1, 2]], ValueError, "too large"),
        (np.zeros((4, 3)), np.zeros((2, 3)), TypeError, "integers"),
        (np.zeros((4, 3)), np.zeros(6, dtype=np.uint32), ValueError, "face_sizes"),
        (np.zeros((4, 3)), [[[0, 1, 2]]], ValueError, "a sequence of faces"),
        (np.zeros((4, 3)), [[0, 1, 2], [[0, 1], [2, 3]]], ValueError, "sequence of vertex indices"),
    ],
)
def test_unusable_arrays_are_refused_with_a_clear_message(vertices, faces, error, message):
    with pytest.raises(error, match=message):
        polymass.mass_properties(vertices, faces)


def test_face_sizes_must_be_integers(cube):
    vertices, faces = cube
    with pytest.raises(TypeError, match="face_sizes"):
        polymass.mass_properties(vertices, np.concatenate(faces), face_sizes=[4.0] * 6)


def test_density_and_mass_together_are_refused(tetrahedron):
    with pytest.raises(ValueError, match="not both"):
        polymass.mass_properties(*tetrahedron, density=1.0, mass=1.0)


@pytest.mark.parametrize("about", ["centre", (1.0, 2.0)])
def test_about_must_be_a_known_name_or_a_point(tetrahedron, about):
    with pytest.raises(ValueError, match="about"):
        polymass.mass_properties(*tetrahedron, about=about)


def test_results_are_read_only(tetrahedron):
    result = polymass.mass_properties(*tetrahedron)
    with pytest.raises(ValueError):
        result.inertia[0, 0] = 1.0
    with pytest.raises(AttributeError):
        result.volume = 2.0
