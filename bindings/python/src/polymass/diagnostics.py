"""What one analysis found: `Diagnostics` (every finding, with its first locations),
`Checks` (which checks ran) and `Shell` (what each shell is), read from a `Mesh`."""

from __future__ import annotations

import dataclasses
import enum
from dataclasses import dataclass

from . import _header
from .errors import Verdict

Edge = tuple[int, int]
# Two face numbers, the lower first.
FacePair = tuple[int, int]


class Checks(enum.IntFlag):
    """Which checks ran to their end (`Diagnostics.checks`)."""

    TOPOLOGY = _header.POLYMASS_CHECKED_TOPOLOGY
    """Open, non-manifold and misoriented edges, non-planar faces."""
    SHELLS = _header.POLYMASS_CHECKED_SHELLS
    """The shells judged: their volumes and how they nest."""
    INTERSECTIONS = _header.POLYMASS_CHECKED_INTERSECTIONS
    """Crossing and touching faces, shells counted twice."""


@dataclass(frozen=True)
class Diagnostics(Verdict):
    """What an analysis found (`Mesh.diagnostics`, `check`), every check the
    options did not skip run to its end. Vertex numbers are the caller's
    indices (after welding: the lowest index at that position); shells are
    numbered as `Mesh.shells` numbers them. Each ``first_*`` tuple holds the
    first (lowest) locations of the finding counted beside it, ascending: up to
    ``POLYMASS_DIAGNOSTIC_LOCATIONS`` (8) of them, none when the count is 0.
    Faces of fewer than 3 vertices, indices out of range and non-finite
    coordinates leave the faces unreadable: the report then holds only those
    findings and the counts."""

    status: int
    """The analysis's verdict, what `mass_properties` with the same options
    reports: 0 (POLYMASS_OK) when a mode answered, else an error status."""
    message: str
    """What is wrong with the surface as given, in words: the message of
    ``solid_status`` ("" for a valid solid), kept when a later mode answered;
    when none answered, each later mode's reason follows."""
    solid_status: int
    """The surface's own verdict as the "solid" mode judges it, whatever mode
    answered: 0 for a valid solid, else its first defect."""
    checks: Checks
    """Which checks ran to their end."""
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
    """Shells (connected pieces) of the surface (0 when the faces are unreadable)."""
    inverted_shells: int
    """Shells inside out (negative volume) that lie inside no solid shell."""
    first_inverted_shells: tuple[int, ...]
    overlapping_shells: int
    """Shells inside a solid of the same sense, whose volume would count twice
    (not with skip_intersection_check=True)."""
    first_overlapping_shells: tuple[int, ...]
    intersecting_face_pairs: int
    """Pairs of faces that cross each other (not with skip_intersection_check=True),
    counted up to 2048 (the C library's POLYMASS_MAX_COUNTED_FACE_PAIRS): at that count
    the check ended there, and every pair count is a lower bound."""
    first_intersecting_face_pairs: tuple[FacePair, ...]
    touching_face_pairs: int
    """Pairs of faces that touch without crossing nor sharing a vertex, such as
    parts resting on each other: legal (not with skip_intersection_check=True)."""
    first_touching_face_pairs: tuple[FacePair, ...]


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


def diagnostics_from_c(report, status: int, message: str) -> Diagnostics:
    """A `Diagnostics` from a polymass_diagnostics and the analysis's verdict."""
    values = {"status": status, "message": message}
    for item in dataclasses.fields(Diagnostics):
        if item.name in values:
            continue
        if item.name == "solid_status":
            values[item.name] = report.status
        elif item.name == "checks":
            values[item.name] = Checks(report.checks)
        elif item.name.startswith("first_"):
            values[item.name] = _locations(getattr(report, item.name))
        else:
            values[item.name] = getattr(report, item.name)
    return Diagnostics(**values)


# POLYMASS_SHELL_* as the names `Shell.kind` takes.
_SHELL_KINDS = {
    _header.POLYMASS_SHELL_UNJUDGED: "unjudged",
    _header.POLYMASS_SHELL_SOLID: "solid",
    _header.POLYMASS_SHELL_CAVITY: "cavity",
    _header.POLYMASS_SHELL_INVERTED: "inverted",
    _header.POLYMASS_SHELL_OVERLAPPING: "overlapping",
    _header.POLYMASS_SHELL_NO_VOLUME: "no_volume",
}


@dataclass(frozen=True)
class Shell:
    """One shell of a surface (`Mesh.shells`): a connected piece, faces sharing a
    vertex (after welding, when the options weld) being in one shell."""

    kind: str
    """"solid" (positive volume, in no other solid), "cavity" (negative, inside a
    solid), "inverted" (negative, inside no solid: inside out), "overlapping"
    (inside a solid of the same sense: counted twice), "no_volume" (encloses no
    volume, to rounding), "unjudged" (the surface failed a check that comes
    before the shells: closed, manifold, oriented, planar), or "unknown" for a
    kind this binding predates. With skip_intersection_check=True nesting is
    judged by bounding boxes, which can show a shell to be inside out but take
    any negative shell within a solid's box for a cavity."""
    face_count: int
    first_face: int
    """The lowest face number of the shell."""
    signed_volume: float
    """Signed so that the whole surface's volume is positive (a surface accepted
    inside out with accept_inverted counts turned): a cavity's is negative; NaN
    when unjudged."""


def shells_from_c(described) -> list[Shell]:
    """`Shell` values from polymass_shell structs."""
    return [
        Shell(
            kind=_SHELL_KINDS.get(shell.kind, "unknown"),
            face_count=shell.face_count,
            first_face=shell.first_face,
            signed_volume=shell.signed_volume,
        )
        for shell in described
    ]
