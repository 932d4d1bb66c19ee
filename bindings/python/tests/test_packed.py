"""polymass.packed_mass_properties: many triangle meshes in shared arrays, every
row bit for bit the single call's, failures in their own rows, arguments that
describe no packed set refused."""

from __future__ import annotations

import numpy as np
import pytest

import polymass
from shapes import convex_hull, star_polyhedron, torus

_COLUMNS = ("volume", "mass", "surface_area", "center_of_mass", "inertia")
_COLUMNS += ("principal_moments", "principal_axes", "error_bound_volume")
_COLUMNS += ("error_bound_center_of_mass", "error_bound_inertia")


def _meshes():
    """Closed triangle meshes of several kinds and sizes, far from the origin."""
    rng = np.random.default_rng(31)
    meshes = [
        star_polyhedron(rng),
        convex_hull(rng),
        torus(3.0, 1.0, 12, 8),
        star_polyhedron(rng, 90),
        torus(2.0, 0.5, 9, 7),
    ]
    return [(vertices + 100.0 * i, np.asarray(faces)) for i, (vertices, faces) in enumerate(meshes)]


def _pack(meshes, global_indices=False):
    """(vertices, faces, vertex_offsets, face_offsets) of the meshes, packed."""
    vertex_offsets = np.cumsum([0] + [len(vertices) for vertices, _ in meshes])
    face_offsets = np.cumsum([0] + [len(faces) for _, faces in meshes])
    faces = [
        faces + (first if global_indices else 0)
        for (_, faces), first in zip(meshes, vertex_offsets)
    ]
    return (
        np.concatenate([vertices for vertices, _ in meshes]),
        np.concatenate(faces).astype(np.int64),
        vertex_offsets,
        face_offsets,
    )


def _assert_row_is_single_call(rows, i, single):
    assert rows.status[i] == 0 and rows.message(i) == "" and rows.error(i) is None
    assert rows.warnings[i] == single.warnings
    expected = {
        "volume": single.volume,
        "mass": single.mass,
        "surface_area": single.surface_area,
        "center_of_mass": single.center_of_mass,
        "inertia": single.inertia,
        "principal_moments": single.principal_moments,
        "principal_axes": single.principal_axes,
        "error_bound_volume": single.error_bound.volume,
        "error_bound_center_of_mass": single.error_bound.center_of_mass,
        "error_bound_inertia": single.error_bound.inertia,
    }
    for name in _COLUMNS:  # bit for bit: the same bytes
        assert getattr(rows, name)[i].tobytes() == np.asarray(expected[name]).tobytes(), name


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("index_dtype", [np.uint32, np.uint16, np.int64])
@pytest.mark.parametrize("global_indices", [False, True])
@pytest.mark.parametrize("threads", [1, 2])
def test_rows_are_single_calls_bit_for_bit(dtype, index_dtype, global_indices, threads):
    meshes = _meshes()
    vertices, faces, vertex_offsets, face_offsets = _pack(meshes, global_indices)
    vertices, faces = vertices.astype(dtype), faces.astype(index_dtype)
    densities = np.linspace(0.5, 3.0, len(meshes))
    rows = polymass.packed_mass_properties(
        vertices,
        faces,
        vertex_offsets,
        face_offsets,
        global_indices=global_indices,
        density=densities,
        threads=threads,
    )
    assert len(rows) == len(meshes) and rows.failed == 0 and rows.ok.all()
    assert rows.inertia.shape == (len(meshes), 3, 3)
    for i, (mesh_vertices, mesh_faces) in enumerate(meshes):
        single = polymass.mass_properties(
            mesh_vertices.astype(dtype), mesh_faces.astype(index_dtype), density=densities[i]
        )
        _assert_row_is_single_call(rows, i, single)


def test_one_mass_or_density_for_all_or_one_each():
    meshes = _meshes()
    packed = _pack(meshes)
    by_mass = polymass.packed_mass_properties(*packed, mass=np.arange(1.0, 6.0))
    by_density = polymass.packed_mass_properties(*packed, density=2700.0)
    assert np.array_equal(by_mass.mass, np.arange(1.0, 6.0))
    for i, (vertices, faces) in enumerate(meshes):
        _assert_row_is_single_call(
            by_mass, i, polymass.mass_properties(vertices, faces, mass=1.0 + i)
        )
        _assert_row_is_single_call(
            by_density, i, polymass.mass_properties(vertices, faces, density=2700.0)
        )
    with pytest.raises(ValueError, match="not both"):
        polymass.packed_mass_properties(*packed, mass=1.0, density=1.0)
    with pytest.raises(ValueError, match="one for each of 5"):
        polymass.packed_mass_properties(*packed, density=[1.0, 2.0])


def test_options_apply_to_every_mesh():
    meshes = _meshes()
    vertices, faces = meshes[2]
    meshes[2] = (vertices, faces[:, ::-1])  # inverted as a whole
    refused = polymass.packed_mass_properties(*_pack(meshes))
    assert refused.failed == 1 and isinstance(refused.error(2), polymass.InvertedError)
    accepted = polymass.packed_mass_properties(*_pack(meshes), accept_inverted=True)
    assert accepted.failed == 0
    assert accepted.warnings[2] & polymass.Warnings.INVERTED
    single = polymass.mass_properties(*meshes[2], accept_inverted=True)
    _assert_row_is_single_call(accepted, 2, single)


def test_a_failed_mesh_is_its_row_alone():
    meshes = _meshes()
    vertices, faces = meshes[1]
    meshes[1] = (vertices, faces[1:])  # open
    vertices, faces, vertex_offsets, face_offsets = _pack(meshes, global_indices=True)
    # Mesh 3 names a vertex of mesh 4: out of its own range.
    faces[face_offsets[3] + 2, 1] = vertex_offsets[4]
    rows = polymass.packed_mass_properties(
        vertices, faces, vertex_offsets, face_offsets, global_indices=True
    )
    assert rows.failed == 2 and list(rows.ok) == [True, False, True, False, True]
    with pytest.raises(polymass.OpenSurfaceError) as single:
        polymass.mass_properties(*meshes[1])
    assert rows.status[1] == polymass.OpenSurfaceError.status
    assert rows.message(1) == single.value.message and "edge" in rows.message(1)
    error = rows.error(3)
    assert isinstance(error, polymass.IndexOutOfRangeError)
    assert f"vertex {vertex_offsets[4]}" in error.message
    assert f"start at {vertex_offsets[3]}" in error.message
    assert set(rows.errors()) == {1, 3}
    for i in (1, 3):
        assert rows.warnings[i] == 0
        for name in _COLUMNS:
            assert np.isnan(getattr(rows, name)[i]).all(), name
    for i in (0, 2, 4):
        _assert_row_is_single_call(rows, i, polymass.mass_properties(*meshes[i]))


def test_read_in_place_from_wider_rows():
    """Positions in a wider array (an interleaved vertex buffer) are read in place."""
    meshes = _meshes()
    vertices, faces, vertex_offsets, face_offsets = _pack(meshes)
    wide = np.zeros((len(vertices), 6))
    wide[:, :3] = vertices
    wide[:, 3:] = np.nan  # normals, not positions
    rows = polymass.packed_mass_properties(
        wide[:, :3], faces.astype(np.uint32), vertex_offsets, face_offsets
    )
    plain = polymass.packed_mass_properties(vertices, faces, vertex_offsets, face_offsets)
    for name in _COLUMNS:
        assert getattr(rows, name).tobytes() == getattr(plain, name).tobytes()


def test_no_mesh():
    rows = polymass.packed_mass_properties(np.zeros((0, 3)), np.zeros((0, 3), np.uint32), [0], [0])
    assert len(rows) == 0 and rows.failed == 0 and rows.inertia.shape == (0, 3, 3)


def test_arguments_that_describe_no_packed_set():
    vertices, faces, vertex_offsets, face_offsets = _pack(_meshes())
    call = polymass.packed_mass_properties
    with pytest.raises(ValueError, match="ends at"):
        call(vertices, faces, vertex_offsets[:-1], face_offsets[:-1])
    with pytest.raises(ValueError, match="ends at"):
        call(vertices[:-1], faces, vertex_offsets, face_offsets)
    with pytest.raises(ValueError, match="one more than the meshes"):
        call(vertices, faces, vertex_offsets, np.r_[0, face_offsets])
    with pytest.raises(ValueError, match="negative"):
        call(vertices, faces, np.r_[-1, vertex_offsets[1:]], face_offsets)
    with pytest.raises(ValueError, match="integer"):
        call(vertices, faces, vertex_offsets.astype(float), face_offsets)
    with pytest.raises(ValueError, match=r"\(f, 3\)"):
        call(vertices, faces.reshape(-1), vertex_offsets, face_offsets)
    descending = vertex_offsets.copy()
    descending[2] = descending[3] + 1
    with pytest.raises(polymass.InvalidArgumentError, match="ascend"):
        call(vertices, faces, descending, face_offsets)


def test_64_bit_indices_that_do_not_fit_fail_their_own_mesh():
    # int64 indices are read in place and narrowed by the library mesh by
    # mesh: a negative one, or one past 2**32 - 1, is its mesh's error only.
    vertices, faces, vertex_offsets, face_offsets = _pack(_meshes())
    assert faces.dtype == np.int64
    call = polymass.packed_mass_properties
    whole = call(vertices, faces, vertex_offsets, face_offsets)
    bad = faces.copy()
    bad[7, 2] = 2**32
    last = len(face_offsets) - 2
    bad[face_offsets[last], 1] = -1
    rows = call(vertices, bad, vertex_offsets, face_offsets)
    mesh = int(np.searchsorted(face_offsets, 7, side="right")) - 1
    assert mesh != last
    for i in range(len(rows)):
        if i in (mesh, last):
            assert isinstance(rows.error(i), polymass.IndexOutOfRangeError)
            assert np.isnan(rows.volume[i])
        else:
            assert rows.status[i] == whole.status[i]
            assert rows.volume[i] == whole.volume[i] or np.isnan(whole.volume[i])
    assert f"face {7 - face_offsets[mesh]} refers to vertex {2**32}" in rows.message(mesh)
    assert f"face 0 refers to vertex {2**64 - 1}" in rows.message(last)
