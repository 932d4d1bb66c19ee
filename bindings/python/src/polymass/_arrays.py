"""NumPy arrays to the C library's mesh description, copying only what must be.

Positions are read in place when they are float64 or float32 in native byte
order with consecutive x, y, z (a row stride of any size is handed to the
library, so ``vertices[:, :3]`` of a wider array is not copied). Indices are
read in place when they are C-contiguous uint32, uint16, or int32 (checked
non-negative, then read as uint32). Anything else is converted to such an array
first, which copies it.

The library is handed pointers made with ``ffi.from_buffer``, which hold the
arrays alive as long as the description. Read in place means read while the
call runs, with the GIL released: another thread must not write to those arrays
meanwhile (an index changed between the library's range check and its use could
make it read out of bounds).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Union, cast

import numpy as np
import numpy.typing as npt

from . import _header
from ._library import ffi, new_struct
from .errors import IndexOutOfRangeError

# What `faces` may be: an (n, k) integer array of n faces of k vertices each, a
# sequence of faces of any sizes, or (with face_sizes) the flat indices.
FacesLike = Union[npt.ArrayLike, Sequence[Sequence[int]]]

_LARGEST_INDEX = 2**32 - 1
# Integers beyond 2**53 have no exact double: refusing them beats rounding.
_LARGEST_EXACT_INTEGER = 2**53


def as_positions(values: npt.ArrayLike, columns: int, *, name: str, keep_float32: bool = True):
    """An (n, columns) float64 or float32 array whose columns are consecutive in memory."""
    array = np.asarray(values)
    if array.ndim != 2 or array.shape[1] != columns:
        raise ValueError(f"{name} must have shape (n, {columns}); got shape {array.shape}")
    kind, size = array.dtype.kind, array.dtype.itemsize
    if kind == "f" and size in (4, 8):
        if size == 4 and not keep_float32:
            array = array.astype(np.float64)
    elif kind == "f" and size == 2:
        array = array.astype(np.float32 if keep_float32 else np.float64)
    elif kind in "iu":
        if array.size and int(np.abs(array).max()) > _LARGEST_EXACT_INTEGER:
            raise ValueError(f"{name} holds integers too large to be exact as float64")
        array = array.astype(np.float64)
    else:
        raise TypeError(
            f"{name} must be float64 or float32 (integers are converted); got {array.dtype}: "
            "convert it explicitly"
        )
    if not array.dtype.isnative:
        array = array.astype(array.dtype.newbyteorder("="))
    # The library takes consecutive coordinates in a row and rows that do not
    # overlap (a stride of at least a row: sliding-window views are copied).
    if array.strides[1] != array.itemsize or (
        len(array) > 1 and array.strides[0] < columns * array.itemsize
    ):
        array = np.ascontiguousarray(array)
    return array


def position_type(positions: np.ndarray) -> int:
    """The POLYMASS_POSITION_* of positions `as_positions` made."""
    if positions.dtype == np.float64:
        return _header.POLYMASS_POSITION_FLOAT64
    return _header.POLYMASS_POSITION_FLOAT32


def row_stride(array: np.ndarray) -> int:
    """The byte stride to hand to the library (0: packed, for a single row)."""
    return array.strides[0] if len(array) > 1 else 0


def rows_buffer(array: np.ndarray):
    """A ``char[]`` over the rows of a 2-D array read in place, from its first
    element to its last row's end (the gaps between rows of a strided view
    included); it keeps ``array`` alive. The rows' elements must be consecutive.
    """
    if array.flags.c_contiguous:
        return ffi.from_buffer(array)
    # The bytes of every row, rows still apart: then the one run of memory from
    # the first row's start to the last row's end (inside the array viewed).
    row_bytes = array.view(np.uint8)
    span = (len(array) - 1) * array.strides[0] + row_bytes.shape[1]
    return ffi.from_buffer(np.lib.stride_tricks.as_strided(row_bytes, (span,), (1,)))


def _out_of_range(indices: np.ndarray, position: int, face_of_position) -> IndexOutOfRangeError:
    face = face_of_position(position)
    return IndexOutOfRangeError(
        f"face {face} refers to vertex {indices[position]}, which cannot exist "
        f"(vertex indices are 0 to {_LARGEST_INDEX})"
    )


def _as_indices(indices: np.ndarray, face_of_position) -> np.ndarray:
    """C-contiguous uint32 or uint16 indices, range-checked where they are converted."""
    if indices.dtype.kind not in "iu":
        raise TypeError(f"face indices must be integers; got {indices.dtype}")
    if indices.dtype.isnative and indices.dtype in (np.uint32, np.uint16):
        return np.ascontiguousarray(indices)
    if indices.size:
        negative = np.flatnonzero(indices < 0)
        if negative.size:
            raise _out_of_range(indices, int(negative[0]), face_of_position)
        if indices.dtype.itemsize > 4 or indices.dtype.kind == "u":
            too_large = np.flatnonzero(indices > _LARGEST_INDEX)
            if too_large.size:
                raise _out_of_range(indices, int(too_large[0]), face_of_position)
    if indices.dtype == np.int32 and indices.dtype.isnative:
        # Checked non-negative: the same bits read as uint32, without a copy.
        return np.ascontiguousarray(indices).view(np.uint32)
    return indices.astype(np.uint32)


@dataclass
class MeshDescription:
    """A polymass_mesh_desc, the arrays its pointers point into, and the buffers
    (``ffi.from_buffer``) that hold them while the description lives."""

    desc: Any
    vertices: np.ndarray
    indices: np.ndarray
    face_sizes: np.ndarray | None
    buffers: tuple


def mesh_description(
    vertices: npt.ArrayLike, faces: FacesLike, face_sizes: npt.ArrayLike | None
) -> MeshDescription:
    positions = as_positions(vertices, 3, name="vertices")
    indices, sizes = _faces(faces, face_sizes)
    desc = new_struct("polymass_mesh_desc")
    desc.position_type = position_type(positions)
    buffers = [rows_buffer(positions), ffi.from_buffer(indices)]
    desc.positions = buffers[0]
    desc.vertex_count = len(positions)
    desc.position_stride = row_stride(positions)
    desc.index_type = (
        _header.POLYMASS_INDEX_UINT16
        if indices.dtype == np.uint16
        else _header.POLYMASS_INDEX_UINT32
    )
    desc.indices = buffers[1]
    desc.index_count = indices.size
    if sizes is not None:
        buffers.append(ffi.from_buffer("uint32_t[]", sizes))
        desc.face_sizes = buffers[-1]
        desc.face_count = sizes.size
    return MeshDescription(desc, positions, indices, sizes, tuple(buffers))


def _faces(faces: FacesLike, face_sizes: npt.ArrayLike | None):
    """(indices, sizes): sizes is None when every face is a triangle."""
    if face_sizes is not None:
        sizes = _as_face_sizes(np.asarray(face_sizes))
        flat = np.asarray(faces)
        if flat.ndim != 1:
            raise ValueError(f"with face_sizes, faces must be the flat indices; got {flat.shape}")
        starts = np.cumsum(sizes) - sizes
        indices = _as_indices(flat, lambda p: int(np.searchsorted(starts, p, side="right")) - 1)
        # All triangles: no sizes needed, if they account for every index (else
        # the library is given them, to say how they do not add up).
        all_triangles = sizes.size and np.all(sizes == 3) and 3 * sizes.size == flat.size
        return indices, (None if all_triangles else sizes)
    if isinstance(faces, np.ndarray) or _is_rectangular(faces):
        table = np.asarray(faces)
        if table.ndim != 2:
            raise ValueError(
                "faces must be an (n, k) integer array, a sequence of faces, or the flat "
                f"indices with face_sizes; got an array of shape {table.shape}"
            )
        count, corners = table.shape
        indices = _as_indices(table.reshape(-1), lambda p: p // corners)
        if corners == 3:
            return indices, None
        return indices, np.full(count, corners, dtype=np.uint32)
    # A ragged sequence of faces. An empty face would read as float64: give it an
    # integer type to join the others.
    ragged = cast(Sequence[Sequence[int]], faces)
    polygons = [np.asarray(face) if len(face) else np.zeros(0, np.uint32) for face in ragged]
    if any(polygon.ndim != 1 for polygon in polygons):
        raise ValueError("each face must be a sequence of vertex indices")
    sizes = np.array([polygon.size for polygon in polygons], dtype=np.uint32)
    flat = np.concatenate(polygons) if polygons else np.zeros(0, dtype=np.uint32)
    starts = np.cumsum(sizes, dtype=np.int64) - sizes
    indices = _as_indices(flat, lambda p: int(np.searchsorted(starts, p, side="right")) - 1)
    return indices, (None if np.all(sizes == 3) else sizes)


def _is_rectangular(faces) -> bool:
    """Whether a sequence of faces has faces of one size (so it is a table)."""
    try:
        lengths = {len(face) for face in faces}
    except TypeError:
        return True  # not a sequence of sequences: np.asarray will say what it is
    return len(lengths) <= 1 and len(faces) > 0


def _as_face_sizes(sizes: np.ndarray) -> np.ndarray:
    if sizes.ndim != 1 or sizes.dtype.kind not in "iu":
        raise TypeError(f"face_sizes must be a 1-D integer array; got {sizes.dtype} {sizes.shape}")
    if sizes.size and (sizes.min() < 0 or int(sizes.max()) > _LARGEST_INDEX):
        raise ValueError("face_sizes must be between 0 and 2**32 - 1")
    return np.ascontiguousarray(sizes, dtype=np.uint32)
