"""`check`: every finding about a surface, instead of the first one as an exception."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from . import _header
from ._arrays import FacesLike, mesh_description
from ._library import context, ffi, lib, new_struct
from ._options import Weld, apply_options
from .errors import Error, error_class, raise_for_status

# Statuses that are about the call, not the mesh: raised rather than reported.
_CALL_FAILURES = (
    _header.POLYMASS_ERROR_INVALID_ARGUMENT,
    _header.POLYMASS_ERROR_OUT_OF_MEMORY,
    _header.POLYMASS_ERROR_INTERNAL,
)

Edge = tuple[int, int]


@dataclass(frozen=True)
class Diagnostics:
    """What `check` found. Vertex numbers are the caller's indices (after welding:
    the lowest index at that position). Each ``first_*`` tuple holds the first
    (lowest) locations of the finding counted beside it, ascending: up to
    ``POLYMASS_DIAGNOSTIC_LOCATIONS`` (8) of them, none when the count is 0."""

    status: int
    """What `mass_properties` would report: 0 (POLYMASS_OK) or an error status."""
    message: str
    """The library's message for that status ("" when it is OK)."""
    face_count: int
    used_vertex_count: int
    edge_count: int
    non_finite_vertices: int
    first_non_finite_vertices: tuple[int, ...]
    out_of_range_indices: int
    first_out_of_range_faces: tuple[int, ...]
    small_faces: int
    first_small_faces: tuple[int, ...]
    degenerate_faces: int
    """Zero-area faces: legal and harmless."""
    first_degenerate_faces: tuple[int, ...]
    open_edges: int
    first_open_edges: tuple[Edge, ...]
    non_manifold_edges: int
    first_non_manifold_edges: tuple[Edge, ...]
    misoriented_edges: int
    first_misoriented_edges: tuple[Edge, ...]
    non_planar_faces: int
    first_non_planar_faces: tuple[int, ...]
    max_non_planarity: float
    """The largest off-plane distance of a polygon face's vertex, relative to its diameter."""
    signed_volume: float
    """Negative when every face is reversed; NaN when the faces could not be integrated."""

    @property
    def ok(self) -> bool:
        """Whether `mass_properties` would succeed with the same options."""
        return self.status == _header.POLYMASS_OK

    @property
    def error(self) -> type[Error] | None:
        """The exception class `mass_properties` would raise, or None."""
        return None if self.ok else error_class(self.status)

    def raise_if_error(self) -> None:
        """Raises what `mass_properties` would raise, if anything."""
        if not self.ok:
            raise error_class(self.status)(self.message, self.status)


def _locations(values) -> tuple[int, ...] | tuple[Edge, ...]:
    """The set entries of a ``first_*`` array: those before the first POLYMASS_NONE."""
    found = []
    for value in values:
        if isinstance(value, int):
            if value == _header.POLYMASS_NONE:
                break
            found.append(value)
        else:
            if value[0] == _header.POLYMASS_NONE:
                break
            found.append((value[0], value[1]))
    return tuple(found)


def check(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    weld: Weld = False,
    accept_inverted: bool = False,
    accept_non_manifold: bool = False,
    planarity_tolerance: float | None = None,
) -> Diagnostics:
    """Runs every check on a surface without stopping at the first finding.

    Takes the arguments of `mass_properties` (the topology checks always run).
    Problems with the mesh are reported in the result, not raised; problems with
    the call itself (InvalidArgumentError, OutOfMemoryError) are raised.
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    ctx = context()
    apply_options(
        ctx,
        weld=weld,
        accept_inverted=accept_inverted,
        accept_non_manifold=accept_non_manifold,
        planarity_tolerance=planarity_tolerance,
    )
    report = new_struct("polymass_diagnostics")
    status = lib.polymass_mesh_check(report, ctx, mesh.desc)
    if status in _CALL_FAILURES:
        raise_for_status(status, ctx)
    message = ffi.string(lib.polymass_context_message(ctx)).decode()
    values = {}
    for item in dataclasses.fields(Diagnostics):
        if item.name == "message":
            values[item.name] = message
        elif item.name.startswith("first_"):
            values[item.name] = _locations(getattr(report, item.name))
        else:
            values[item.name] = getattr(report, item.name)
    return Diagnostics(**values)


def shells(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    weld: Weld = False,
) -> np.ndarray:
    """The shell (connected piece of surface) of each face: an array of face
    numbers 0 .. n_shells - 1, numbered in the order of the shells' first faces.

    Faces sharing a vertex are in one shell; with ``weld`` (True, or a relative
    tolerance) vertices at the same position are one first, so a triangle soup
    splits as its solid does. Indices out of range and non-finite coordinates
    raise, as in `mass_properties`; the topology is not checked. Each shell can
    then be checked or computed on its own (a cavity has a negative volume).
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    ctx = context()
    apply_options(ctx, weld=weld)
    face_count = mesh.face_sizes.size if mesh.face_sizes is not None else mesh.indices.size // 3
    of_face = np.empty(face_count, dtype=np.uint32)
    count = ffi.new("uint64_t *")
    status = lib.polymass_mesh_shells(
        ffi.cast("uint32_t *", of_face.ctypes.data), count, ctx, mesh.desc
    )
    raise_for_status(status, ctx)
    return of_face
