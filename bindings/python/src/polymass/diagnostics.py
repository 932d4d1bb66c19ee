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
# Two face numbers, the lower first.
FacePair = tuple[int, int]


@dataclass(frozen=True)
class Diagnostics:
    """What `check` found. Vertex numbers are the caller's indices (after welding:
    the lowest index at that position); shells are numbered as `shells` numbers
    them. Each ``first_*`` tuple holds the first (lowest) locations of the
    finding counted beside it, ascending: up to
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
    shell_count: int
    """Shells (connected pieces) of the surface, counted once it is closed and oriented."""
    inverted_shells: int
    """Shells inside out (negative volume) that lie inside no solid shell."""
    first_inverted_shells: tuple[int, ...]
    overlapping_shells: int
    """Shells inside a solid of the same sense, whose volume would count twice
    (not with skip_intersection_check=True)."""
    first_overlapping_shells: tuple[int, ...]
    intersecting_face_pairs: int
    """Pairs of faces that cross each other (not with skip_intersection_check=True)."""
    first_intersecting_face_pairs: tuple[FacePair, ...]
    touching_face_pairs: int
    """Pairs of faces that touch without crossing nor sharing a vertex, such as
    parts resting on each other: legal (not with skip_intersection_check=True)."""
    first_touching_face_pairs: tuple[FacePair, ...]

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


def _locations(values) -> tuple[int, ...] | tuple[Edge, ...] | tuple[FacePair, ...]:
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
    skip_intersection_check: bool = False,
    threads: int | None = None,
) -> Diagnostics:
    """Runs every check on a surface without stopping at the first finding.

    Takes the arguments of `mass_properties` (the topology checks always run).
    Problems with the mesh are reported in the result, not raised; problems with
    the call itself (InvalidArgumentError, OutOfMemoryError) are raised.

    Crossing and touching faces and shells nested twice are found too
    (IntersectingSurfaceError, with the face pairs), as `mass_properties` finds
    them by default, unless ``skip_intersection_check=True``.
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    ctx = context()
    apply_options(
        ctx,
        weld=weld,
        accept_inverted=accept_inverted,
        accept_non_manifold=accept_non_manifold,
        planarity_tolerance=planarity_tolerance,
        skip_intersection_check=skip_intersection_check,
        threads=threads,
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
    threads: int | None = None,
) -> np.ndarray:
    """The shell (connected piece of surface) of each face: an array of face
    numbers 0 .. n_shells - 1, numbered in the order of the shells' first faces.

    Faces sharing a vertex are in one shell; with ``weld`` (True, or a relative
    tolerance) vertices at the same position are one first, so a triangle soup
    splits as its solid does. Indices out of range and non-finite coordinates
    raise, as in `mass_properties`; the topology is not checked. Each shell can
    then be checked or computed on its own (a cavity has a negative volume);
    `shell_list` says what each one is.
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    ctx = context()
    apply_options(ctx, weld=weld, threads=threads)
    face_count = mesh.face_sizes.size if mesh.face_sizes is not None else mesh.indices.size // 3
    of_face = np.empty(face_count, dtype=np.uint32)
    count = ffi.new("uint64_t *")
    status = lib.polymass_mesh_shells(
        ffi.cast("uint32_t *", of_face.ctypes.data), count, ctx, mesh.desc
    )
    raise_for_status(status, ctx)
    return of_face


# POLYMASS_SHELL_* as the names `Shell.kind` takes.
_SHELL_KINDS = {
    _header.POLYMASS_SHELL_SOLID: "solid",
    _header.POLYMASS_SHELL_CAVITY: "cavity",
    _header.POLYMASS_SHELL_INVERTED: "inverted",
    _header.POLYMASS_SHELL_OVERLAPPING: "overlapping",
    _header.POLYMASS_SHELL_NO_VOLUME: "no_volume",
}
# Room for this many shells in the first call: most surfaces need no second one.
_SHELLS_FIRST_GUESS = 16


@dataclass(frozen=True)
class Shell:
    """One shell of a closed surface, as `shell_list` describes it."""

    kind: str
    """"solid" (positive volume, in no other solid), "cavity" (negative, inside a
    solid), "inverted" (negative, inside no solid: inside out), "overlapping"
    (inside a solid of the same sense: counted twice), "no_volume" (encloses no
    volume, to rounding), or "unknown" for a kind this binding predates."""
    face_count: int
    first_face: int
    """The lowest face number of the shell."""
    signed_volume: float
    """Signed so that the whole surface's volume is positive (a surface accepted
    inside out with accept_inverted counts turned): a cavity's is negative."""


def shell_list(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    weld: Weld = False,
    accept_inverted: bool = False,
    accept_non_manifold: bool = False,
    planarity_tolerance: float | None = None,
    skip_intersection_check: bool = False,
    threads: int | None = None,
) -> list[Shell]:
    """What each shell of a closed surface is: a list of `Shell`, shell i being
    the one `shells` numbers i.

    Takes the arguments of `mass_properties`. The surface must pass the checks
    that come before the shells (closed, manifold, oriented, planar, with a
    volume): otherwise their exception is raised. The shells are described
    whether or not they pass themselves, so an inside-out or overlapping shell
    is listed rather than raised. The nesting of the shells is counted exactly;
    with ``skip_intersection_check=True`` it is judged by bounding boxes, which
    can show a shell to be inside out but take any negative shell within a
    solid's box for a cavity.
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    ctx = context()
    apply_options(
        ctx,
        weld=weld,
        accept_inverted=accept_inverted,
        accept_non_manifold=accept_non_manifold,
        planarity_tolerance=planarity_tolerance,
        skip_intersection_check=skip_intersection_check,
        threads=threads,
    )
    count = ffi.new("uint64_t *")
    capacity = _SHELLS_FIRST_GUESS
    while True:
        described = ffi.new("polymass_shell[]", capacity)
        for shell in described:
            shell.struct_size = ffi.sizeof("polymass_shell")
        status = lib.polymass_mesh_shell_list(described, capacity, count, ctx, mesh.desc)
        raise_for_status(status, ctx)
        if count[0] <= capacity:
            break
        capacity = count[0]
    return [
        Shell(
            kind=_SHELL_KINDS.get(shell.kind, "unknown"),
            face_count=shell.face_count,
            first_face=shell.first_face,
            signed_volume=shell.signed_volume,
        )
        for shell in described[0 : count[0]]
    ]
