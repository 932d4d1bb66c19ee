"""Many triangle meshes packed into shared arrays, as datasets keep them:
`packed_mass_properties`, one ``polymass_packed_compute`` call.

Mesh i is the vertices ``vertex_offsets[i]:vertex_offsets[i + 1]`` and the
triangles ``face_offsets[i]:face_offsets[i + 1]`` of the shared arrays, its
indices counted from its own first vertex or, as PyTorch3D's packed form
(``verts_packed``, ``faces_packed``) has them, from the first vertex of all
(``global_indices=True``). The arrays are read in place, as `mass_properties`
reads a mesh's; the results come back as NumPy columns, one row per mesh, with
a status per mesh: a mesh's failure is its row's and stops no other. Every row
is bit for bit what `mass_properties` gives for that mesh alone, whatever the
number of threads.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _header
from ._arrays import _as_indices, as_positions, position_type, row_stride, rows_buffer
from ._library import ffi, lib, new_struct, working_context
from ._options import Options, c_options, gather
from .errors import Error, error_class, raise_for_status


@dataclass(frozen=True, eq=False)
class PackedMassProperties:
    """The mass properties of packed meshes in columns: row i is mesh i's.

    status: (m,) int32: 0 where the mesh was answered, else its status (the
        ``POLYMASS_ERROR_*`` code of the `polymass.Error` subclass `error` gives).
    warnings: (m,) uint32: bits of `polymass.Warnings` (0 for a failed mesh).
    volume (L^3), mass (M), surface_area (L^2): (m,).
    center_of_mass: (m, 3), L.
    inertia: (m, 3, 3) about the centre of mass, M*L^2, the products of inertia
        negated off the diagonal (as `MassProperties.inertia`).
    principal_moments: (m, 3), ascending; principal_axes: (m, 3, 3), the axes as
        columns (as `MassProperties.principal_axes`).
    error_bound_volume, error_bound_center_of_mass, error_bound_inertia: (m,),
        as `MassProperties.error_bound`'s.
    A failed mesh's numbers are NaN.
    """

    status: np.ndarray
    warnings: np.ndarray
    volume: np.ndarray
    mass: np.ndarray
    surface_area: np.ndarray
    center_of_mass: np.ndarray
    inertia: np.ndarray
    principal_moments: np.ndarray
    principal_axes: np.ndarray
    error_bound_volume: np.ndarray
    error_bound_center_of_mass: np.ndarray
    error_bound_inertia: np.ndarray
    messages: np.ndarray
    """(m,) bytes: why mesh i failed (b"" when it did not); see `message`."""

    @classmethod
    def _empty(cls, count: int) -> PackedMassProperties:
        def column(*shape: int) -> np.ndarray:
            return np.empty((count, *shape), dtype=np.float64)

        return cls(
            status=np.empty(count, dtype=np.int32),
            warnings=np.empty(count, dtype=np.uint32),
            volume=column(),
            mass=column(),
            surface_area=column(),
            center_of_mass=column(3),
            inertia=column(3, 3),
            principal_moments=column(3),
            principal_axes=column(3, 3),
            error_bound_volume=column(),
            error_bound_center_of_mass=column(),
            error_bound_inertia=column(),
            messages=np.empty(count, dtype=f"S{_header.POLYMASS_BATCH_MESSAGE_SIZE}"),
        )

    def _c_results(self) -> tuple[Any, list]:
        """The polymass_packed_results writing into these columns, and the
        buffers that keep them alive."""
        results = new_struct("polymass_packed_results")
        buffers = []
        for name in (
            "status",
            "warnings",
            "volume",
            "mass",
            "surface_area",
            "center_of_mass",
            "inertia",
            "principal_moments",
            "principal_axes",
            "error_bound_volume",
            "error_bound_center_of_mass",
            "error_bound_inertia",
            "messages",
        ):
            column = getattr(self, name)
            if column.size:  # an empty column stays NULL: nothing to write
                buffers.append(ffi.from_buffer(column, require_writable=True))
                setattr(results, name, ffi.cast(ffi.typeof(getattr(results, name)), buffers[-1]))
        return results, buffers

    def __len__(self) -> int:
        return len(self.status)

    @property
    def ok(self) -> np.ndarray:
        """(m,) bool: which meshes were answered."""
        return self.status == _header.POLYMASS_OK

    @property
    def failed(self) -> int:
        """How many meshes failed."""
        return int(np.count_nonzero(self.status != _header.POLYMASS_OK))

    def message(self, i: int) -> str:
        """Why mesh i failed ("" when it did not)."""
        return bytes(self.messages[i]).decode("utf-8", "replace")

    def error(self, i: int) -> Error | None:
        """Mesh i's failure as the `polymass.Error` subclass of its status (not
        raised), or None when it was answered."""
        status = int(self.status[i])
        if status == _header.POLYMASS_OK:
            return None
        return error_class(status)(self.message(i), status)

    def errors(self) -> dict[int, Error]:
        """Every failed mesh's `polymass.Error`, by mesh."""
        return {int(i): self.error(int(i)) for i in np.flatnonzero(~self.ok)}  # type: ignore[misc]


def _triangle_indices(table: np.ndarray) -> np.ndarray:
    """The (f, 3) triangles as the flat indices the library reads in place:
    64-bit integers (PyTorch's int64) as unsigned 64-bit, which the library
    narrows mesh by mesh (a negative index, or one past 2**32 - 1, is then
    its own mesh's out-of-range index); anything else as `mass_properties`
    converts indices."""
    flat = table.reshape(-1)
    if flat.dtype.kind in "iu" and flat.dtype.itemsize == 8 and flat.dtype.isnative:
        return np.ascontiguousarray(flat).view(np.uint64)
    return _as_indices(flat, lambda position: position // 3)


def _offsets(values: npt.ArrayLike, total: int, name: str, unit: str) -> np.ndarray:
    """Offsets as the library reads them: uint64, C-contiguous; the last must be
    the length of the array they cut (the library cannot know it)."""
    offsets = np.asarray(values)
    if offsets.ndim != 1 or offsets.size == 0 or offsets.dtype.kind not in "iu":
        raise ValueError(
            f"{name} must be a 1-D integer array of the mesh count + 1 offsets, from 0; "
            f"got {offsets.dtype} of shape {offsets.shape}"
        )
    if int(offsets[-1]) != total:
        raise ValueError(
            f"{name} ends at {int(offsets[-1])} but there are {total} {unit}: the last "
            "offset is the end of the last mesh"
        )
    if offsets.dtype.kind == "i" and offsets.min() < 0:
        raise ValueError(f"{name} holds a negative offset, {int(offsets.min())}")
    return np.ascontiguousarray(offsets, dtype=np.uint64)


def _mass_values(density, mass, count: int) -> tuple[int, np.ndarray | None]:
    """The mass mode and the per-mesh values: one for every mesh, or one each."""
    if density is not None and mass is not None:
        raise ValueError("give density or mass, not both")
    if density is None and mass is None:
        return _header.POLYMASS_MASS_FROM_DENSITY, None
    mode, given, name = (
        (_header.POLYMASS_MASS_FROM_DENSITY, density, "density")
        if mass is None
        else (_header.POLYMASS_MASS_FROM_TOTAL, mass, "mass")
    )
    values = np.asarray(given, dtype=np.float64)
    if values.ndim == 0:
        values = np.full(count, float(values))
    if values.shape != (count,):
        raise ValueError(f"{name} has shape {values.shape}: one value, or one for each of {count}")
    return mode, np.ascontiguousarray(values)


def packed_mass_properties(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    vertex_offsets: npt.ArrayLike,
    face_offsets: npt.ArrayLike,
    *,
    global_indices: bool = False,
    density: float | npt.ArrayLike | None = None,
    mass: float | npt.ArrayLike | None = None,
    options: Options | None = None,
    threads: int | None = None,
    **option_fields: Any,
) -> PackedMassProperties:
    """The mass properties of many triangle meshes packed into shared arrays.

    vertices: (n, 3) float64 or float32 array: every mesh's vertices, one mesh
        after another. Read in place as `mass_properties` reads it (any row
        stride; other layouts are copied).
    faces: (f, 3) integer array: every mesh's triangles, counter-clockwise seen
        from outside. uint32, uint16, int32 (checked non-negative) and 64-bit
        integers (PyTorch's int64: the library narrows them mesh by mesh, and
        a negative or too large index fails its own mesh) are read in place;
        other integer types are checked and converted to uint32.
    vertex_offsets, face_offsets: the mesh count + 1 offsets each, ascending
        from 0 to len(vertices) and len(faces): mesh i is
        ``vertices[vertex_offsets[i]:vertex_offsets[i + 1]]`` and
        ``faces[face_offsets[i]:face_offsets[i + 1]]``.
    global_indices: False: mesh i's indices count from its own first vertex;
        True: from ``vertices[0]`` (PyTorch3D's ``faces_packed()``), each still
        within its mesh's own vertices.
    density (M/L^3) or mass (M), not both: one for every mesh, or an (m,) array
        with one per mesh. Neither: density 1.
    options (and its fields as keywords): as `mass_properties`'s, for every mesh.
    threads: how many of the library's threads take the meshes (None: one);
        every count gives the same bits.

    From PyTorch3D's ``Meshes``: ``packed_mass_properties(m.verts_packed(),
    m.faces_packed(), np.r_[0, m.num_verts_per_mesh().cumsum(0)],
    np.r_[0, m.num_faces_per_mesh().cumsum(0)], global_indices=True)`` (CPU
    tensors, as NumPy arrays).

    Returns a `PackedMassProperties`: each mesh's numbers, or its status and
    message. Arguments that describe no packed set (offsets that do not ascend
    or do not end at the arrays' ends, a shape that is not a triangle table)
    raise `ValueError` (or `polymass.InvalidArgumentError`) at once. The GIL is
    released while the library computes.
    """
    chosen = c_options(gather(options, option_fields))
    positions = as_positions(vertices, 3, name="vertices")
    table = np.asarray(faces)
    if table.ndim != 2 or table.shape[1] != 3:
        raise ValueError(f"faces must be an (f, 3) integer array of triangles; got {table.shape}")
    indices = _triangle_indices(table)
    vertex_starts = _offsets(vertex_offsets, len(positions), "vertex_offsets", "vertices")
    face_starts = _offsets(face_offsets, len(table), "face_offsets", "faces")
    if len(vertex_starts) != len(face_starts):
        raise ValueError(
            f"vertex_offsets has {len(vertex_starts)} offsets and face_offsets "
            f"{len(face_starts)}: one more than the meshes, each"
        )
    count = len(vertex_starts) - 1
    index_starts = face_starts * np.uint64(3)
    mass_mode, mass_values = _mass_values(density, mass, count)

    meshes = new_struct("polymass_packed_meshes")
    buffers = [
        rows_buffer(positions),
        ffi.from_buffer(indices),
        ffi.from_buffer("uint64_t[]", vertex_starts),
        ffi.from_buffer("uint64_t[]", index_starts),
    ]
    meshes.position_type = position_type(positions)
    meshes.positions = buffers[0]
    meshes.position_stride = row_stride(positions)
    meshes.index_type = {
        np.dtype(np.uint16): _header.POLYMASS_INDEX_UINT16,
        np.dtype(np.uint64): _header.POLYMASS_INDEX_UINT64,
    }.get(indices.dtype, _header.POLYMASS_INDEX_UINT32)
    meshes.index_base = (
        _header.POLYMASS_INDICES_GLOBAL if global_indices else _header.POLYMASS_INDICES_LOCAL
    )
    meshes.indices = buffers[1]
    meshes.mesh_count = count
    meshes.vertex_offsets = buffers[2]
    meshes.index_offsets = buffers[3]
    meshes.mass_mode = mass_mode
    if mass_values is not None:
        buffers.append(ffi.from_buffer("double[]", mass_values))
        meshes.mass_values = buffers[-1]

    rows = PackedMassProperties._empty(count)
    results, columns = rows._c_results()
    ctx = working_context(threads)
    failed = ffi.new("uint64_t*")
    raise_for_status(lib.polymass_packed_compute(results, failed, ctx, meshes, chosen), ctx)
    del buffers, columns  # held until the library has returned
    return rows
