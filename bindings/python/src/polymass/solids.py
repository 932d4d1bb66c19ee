"""Mass properties of closed polyhedral surfaces: `mass_properties` and `Mesh`.

Units are the caller's: lengths in L, density in M/L^3, mass in M, inertia in
M*L^2; without a density or a mass the density is 1, so mass == volume.

Inertia sign convention: I = integral of rho * (|r|^2 * Identity - r r^T) dV,
so Ixx = integral rho (y^2 + z^2) dV and the off-diagonal terms are the NEGATED
products of inertia, Ixy = -integral rho x y dV: the tensor URDF, SDFormat,
MuJoCo (fullinertia), PhysX and Bullet take. About a point P:
I_P = I_C + m (|d|^2 Identity - d d^T), d = C - P.

Faces are counter-clockwise seen from outside (normals point out).
"""

from __future__ import annotations

import enum
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal, Union

import numpy as np
import numpy.typing as npt

from . import _header
from ._arrays import FacesLike, mesh_description
from ._library import context, ffi, lib, new_struct
from ._options import Weld, apply_options
from .errors import raise_for_status

# Where `inertia_point` is taken: the centre of mass, the origin, or any point.
About = Union[Literal["com", "origin"], Sequence[float], npt.NDArray[np.floating]]


class Warnings(enum.IntFlag):
    """What the library accepted but wants you to know (MassProperties.warnings)."""

    INVERTED = _header.POLYMASS_WARNING_INVERTED
    """Every face was reversed; the result is for the faces turned the right way."""
    DEGENERATE_FACES = _header.POLYMASS_WARNING_DEGENERATE_FACES
    """Some faces have zero area: harmless."""
    UNCHECKED = _header.POLYMASS_WARNING_UNCHECKED
    """The topology checks were skipped (skip_checks=True)."""
    NON_MANIFOLD = _header.POLYMASS_WARNING_NON_MANIFOLD
    """Non-manifold edges were accepted (accept_non_manifold=True)."""
    TOUCHING_FACES = _header.POLYMASS_WARNING_TOUCHING_FACES
    """Faces touch without crossing, such as parts resting on each other: found by
    the intersection check (on by default), and `check` lists the face pairs."""
    REPAIRED = _header.POLYMASS_WARNING_REPAIRED
    """Not a valid solid: the surface was repaired (see `Provenance`)."""
    SHELL = _header.POLYMASS_WARNING_SHELL
    """Computed as a thin wall (shell=thickness), not as a solid."""
    HULL = _header.POLYMASS_WARNING_HULL
    """The convex hull, not the solid (an upper bound)."""


def _frozen(values, shape: tuple[int, ...]) -> np.ndarray:
    array = np.array(ffi.unpack(values, int(np.prod(shape))), dtype=np.float64).reshape(shape)
    array.setflags(write=False)
    return array


@dataclass(frozen=True)
class ErrorBound:
    """Bounds on the rounding errors of a result, absolute, in its units (docs/error_bound.md).

    They hold for the surface as given (its coordinates taken as exact).
    volume: L^3. center_of_mass: L, of each coordinate. inertia: M*L^2, of each
    entry of the tensor about the centre of mass. principal_moments: of each.
    principal_axes: radians, of each axis the moments determine: it grows as
    two moments approach each other, and is pi/2 when they are closer than
    their bounds tell apart.
    """

    volume: float
    center_of_mass: float
    inertia: float
    principal_moments: float
    principal_axes: float


@dataclass(frozen=True)
class Repair:
    """One kind of repair: how many, and the first (lowest) locations: face
    numbers, vertex numbers for holes (each hole's lowest vertex), vertex pairs
    for split edges."""

    count: int
    first: tuple


@dataclass(frozen=True)
class Provenance:
    """How the answer was reached (`mass_properties` with repair, shell, hull or fallback).

    mode: "solid" (exact, as given), "repaired", "shell" or "hull".
    repairs: for "repaired", each kind of fix made, by name: reoriented_faces,
        turned_shells, duplicate_faces, degenerate_faces, triangulated_faces,
        split_edges, holes (a `Repair` each).
    cap_area, cap_area_fraction: the caps over holes, and their share of the
        repaired surface.
    approximation_bound: the approximation's share of `MassProperties.error_bound`
        (volume, center_of_mass, inertia; 0 for an exact answer).
    shell_thickness, shell_area: for "shell".
    hull_vertex_count, hull_triangle_count, hull_volume: for "hull".
    """

    mode: str = "solid"
    repairs: dict = field(default_factory=dict)
    cap_area: float = 0.0
    cap_area_fraction: float = 0.0
    approximation_bound: dict = field(
        default_factory=lambda: {"volume": 0.0, "center_of_mass": 0.0, "inertia": 0.0}
    )
    shell_thickness: float = 0.0
    shell_area: float = 0.0
    hull_vertex_count: int = 0
    hull_triangle_count: int = 0
    hull_volume: float = 0.0

    @classmethod
    def _from_c(cls, p) -> Provenance:
        modes = {
            _header.POLYMASS_MODE_REPAIR: "repaired",
            _header.POLYMASS_MODE_SHELL: "shell",
            _header.POLYMASS_MODE_HULL: "hull",
        }
        repairs = {}
        for name in (
            "reoriented_faces",
            "turned_shells",
            "duplicate_faces",
            "degenerate_faces",
            "triangulated_faces",
            "split_edges",
            "holes",
        ):
            count = getattr(p, name)
            if count:
                first = getattr(p, "first_" + name)
                kept = min(count, _header.POLYMASS_DIAGNOSTIC_LOCATIONS)
                locations = [
                    tuple(first[i]) if name == "split_edges" else first[i] for i in range(kept)
                ]
                repairs[name] = Repair(count, tuple(locations))
        return cls(
            mode=modes.get(p.mode, "solid"),
            repairs=repairs,
            cap_area=p.cap_area,
            cap_area_fraction=p.cap_area_fraction,
            approximation_bound={
                "volume": p.approximation_bound_volume,
                "center_of_mass": p.approximation_bound_center_of_mass,
                "inertia": p.approximation_bound_inertia,
            },
            shell_thickness=p.shell_thickness,
            shell_area=p.shell_area,
            hull_vertex_count=p.hull_vertex_count,
            hull_triangle_count=p.hull_triangle_count,
            hull_volume=p.hull_volume,
        )


# eq=False: arrays have no single truth value, so a field-wise == would raise.
@dataclass(frozen=True, eq=False)
class MassProperties:
    """The mass properties of a solid as a body. Arrays are read-only float64.

    volume: L^3; mass: M; density: M/L^3; surface_area: L^2.
    center_of_mass: (3,), L.
    inertia: (3, 3) about the centre of mass, M*L^2, with the negated products
        of inertia off the diagonal (Ixy = -integral rho x y dV).
    inertia_origin: (3, 3) about (0, 0, 0).
    inertia_point: (3, 3) about ``point`` (the ``about`` argument).
    point: (3,) the point of ``inertia_point``.
    principal_moments: (3,) eigenvalues of ``inertia``, ascending.
    principal_axes: (3, 3) rotation R (det R = +1) whose columns are the
        principal axes: inertia = R @ diag(principal_moments) @ R.T.
    warnings: what was accepted (see `Warnings`).
    error_bound: bounds on the rounding errors (see `ErrorBound`), and on the
        approximation when a mode other than the solid answered.
    provenance: how the answer was reached (see `Provenance`).
    """

    volume: float
    mass: float
    density: float
    surface_area: float
    center_of_mass: np.ndarray
    inertia: np.ndarray
    inertia_origin: np.ndarray
    inertia_point: np.ndarray
    point: np.ndarray
    principal_moments: np.ndarray
    principal_axes: np.ndarray
    warnings: Warnings
    error_bound: ErrorBound
    provenance: Provenance = field(default_factory=Provenance)

    @classmethod
    def _from_c(cls, result, point: np.ndarray | None, provenance=None) -> MassProperties:
        """From a polymass_mass_properties; ``point`` None means about the centre of mass."""
        center = _frozen(result.center_of_mass, (3,))
        inertia = _frozen(result.inertia, (3, 3))
        return cls(
            volume=result.volume,
            mass=result.mass,
            density=result.density,
            surface_area=result.surface_area,
            center_of_mass=center,
            inertia=inertia,
            inertia_origin=_frozen(result.inertia_origin, (3, 3)),
            inertia_point=inertia if point is None else _frozen(result.inertia_point, (3, 3)),
            point=center if point is None else point,
            principal_moments=_frozen(result.principal_moments, (3,)),
            principal_axes=_frozen(result.principal_axes, (3, 3)),
            warnings=Warnings(result.warnings),
            error_bound=ErrorBound(
                volume=result.error_bound_volume,
                center_of_mass=result.error_bound_center_of_mass,
                inertia=result.error_bound_inertia,
                principal_moments=result.error_bound_principal_moments,
                principal_axes=result.error_bound_principal_axes,
            ),
            provenance=Provenance() if provenance is None else Provenance._from_c(provenance),
        )


def _mass_desc(density: float | None, mass: float | None, about: About):
    """(polymass_mass_desc, the point as an array or None for the centre of mass)."""
    if density is not None and mass is not None:
        raise ValueError("give density or mass, not both")
    desc = new_struct("polymass_mass_desc")
    if mass is not None:
        desc.mass_mode = _header.POLYMASS_MASS_FROM_TOTAL
        desc.mass = mass
    else:
        desc.mass_mode = _header.POLYMASS_MASS_FROM_DENSITY
        desc.density = 1.0 if density is None else density
    if isinstance(about, str):
        if about == "com":
            return desc, None
        if about != "origin":
            raise ValueError(f'about must be "com", "origin" or a point (x, y, z); got {about!r}')
        point = np.zeros(3)
    else:
        point = np.array(about, dtype=np.float64)
        if point.shape != (3,):
            raise ValueError(f"about must be a point (x, y, z); got shape {point.shape}")
    desc.point = point.tolist()
    point.setflags(write=False)
    return desc, point


def _properties(function, *arguments, density, mass, about) -> MassProperties:
    desc, point = _mass_desc(density, mass, about)
    result = new_struct("polymass_mass_properties")
    ctx = context()
    raise_for_status(function(result, ctx, *arguments, desc), ctx)
    return MassProperties._from_c(result, point)


def mass_properties(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    density: float | None = None,
    mass: float | None = None,
    about: About = "com",
    weld: Weld = False,
    skip_checks: bool = False,
    accept_inverted: bool = False,
    accept_non_manifold: bool = False,
    planarity_tolerance: float | None = None,
    skip_intersection_check: bool = False,
    repair: bool = False,
    shell: float | None = None,
    hull: bool = False,
    fallback: Sequence[str] = (),
    threads: int | None = None,
) -> MassProperties:
    """Volume, mass, centre of mass, inertia and principal axes of a closed surface.

    vertices: (n, 3) float64 or float32 array, in length unit L. Read in place
        (no copy) when each row's x, y, z are consecutive in memory, whatever the
        row stride: ``vertices[:, :3]`` of an (n, 6) array is not copied. Other
        layouts are copied; integer coordinates are converted to float64.
    faces: counter-clockwise seen from outside, either
        - an (m, 3) integer array of triangles (or (m, k): m faces of k vertices),
        - a sequence of faces of any sizes ([[0, 1, 2, 3], [0, 4, 1], ...]), or
        - with ``face_sizes``: the flat indices of all faces, one after another.
        uint32 and uint16 C-contiguous arrays, and int32 ones (checked
        non-negative), are read in place; other integer types are range-checked
        and converted to uint32, which copies them.
    face_sizes: the number of vertices of each face, adding up to len(faces).
    density: M/L^3, or ``mass``: M (not both). Neither: density 1.
    about: the point of ``inertia_point``: "com" (default), "origin" or (x, y, z).
    weld: for triangle soups (STL): True treats vertices at exactly the same
        position as one for the topology checks; a float is a tolerance relative
        to the largest extent of the mesh (at most 1e-3). The integrals do not
        depend on it.
    skip_checks: trusted input: skip the closed, manifold, orientation and
        planarity checks, and the intersection check with them (indices and
        finiteness are always checked).
    accept_inverted: a solid whose faces are all reversed gives the properties
        of the solid turned the right way, with Warnings.INVERTED, instead of
        raising InvertedError.
    accept_non_manifold: accept edges shared by more than two faces when they
        are traversed as often one way as the other (solids touching at an edge).
    planarity_tolerance: how far a polygon face's vertex may be off its plane,
        relative to the face's diameter (None or 0: 1e-6).
    skip_intersection_check: for trusted input only. By default faces that
        cross each other and shells inside a solid of the same sense (whose
        volume would be counted twice: overlapping parts exported as one file)
        are refused with IntersectingSurfaceError, how shells nest judged
        exactly, and faces that only touch give Warnings.TOUCHING_FACES; True
        skips that check, which is most of the call's time (see the README),
        and two overlapping parts then pass with their overlap counted twice.
        The check never changes a result it accepts.
    repair: a surface that is not a valid solid is repaired where the fix is
        unique (orientation, duplicate and two-vertex faces, non-planar
        polygons, holes, balanced non-manifold edges); the result's
        `provenance` says what was done and its error_bound how far off it
        can be (docs/repair.md). A valid solid is answered exactly, as without.
    shell: the surface as a thin wall of this thickness (L): mass =
        density * thickness * area; open surfaces are fine.
    hull: the convex hull of the vertices (an upper bound of the solid).
    fallback: modes tried in order after the solid: a list (or a
        comma-separated string) of "repair", "shell" (with shell=thickness)
        and "hull", such as ["repair", "hull"].
    threads: how many threads the library may use for the call (None: its
        default, one); every count gives the same bits.

    Returns a `MassProperties`; raises a subclass of `polymass.Error` saying what
    is wrong and where. The GIL is released while the library computes.
    """
    mesh = mesh_description(vertices, faces, face_sizes)
    apply_options(
        context(),
        weld=weld,
        skip_checks=skip_checks,
        accept_inverted=accept_inverted,
        accept_non_manifold=accept_non_manifold,
        planarity_tolerance=planarity_tolerance,
        skip_intersection_check=skip_intersection_check,
        repair=repair,
        shell=shell,
        hull=hull,
        fallback=fallback,
        threads=threads,
    )
    desc, point = _mass_desc(density, mass, about)
    result = new_struct("polymass_mass_properties")
    provenance = new_struct("polymass_provenance")
    ctx = context()
    raise_for_status(
        lib.polymass_mass_properties_with_provenance(
            result, provenance, ctx, mesh.desc, desc, ffi.NULL
        ),
        ctx,
    )
    return MassProperties._from_c(result, point, provenance)


class Mesh:
    """A validated, integrated solid: compute it once, then its properties as often as needed.

    Takes the arguments of `mass_properties` that describe the surface and how it
    is checked; it keeps the integrals, not the arrays. A Mesh is immutable and
    may be used from many threads at once.
    """

    def __init__(
        self,
        vertices: npt.ArrayLike,
        faces: FacesLike,
        *,
        face_sizes: npt.ArrayLike | None = None,
        weld: Weld = False,
        skip_checks: bool = False,
        accept_inverted: bool = False,
        accept_non_manifold: bool = False,
        planarity_tolerance: float | None = None,
        skip_intersection_check: bool = False,
        threads: int | None = None,
    ) -> None:
        mesh = mesh_description(vertices, faces, face_sizes)
        ctx = context()
        apply_options(
            ctx,
            weld=weld,
            skip_checks=skip_checks,
            accept_inverted=accept_inverted,
            accept_non_manifold=accept_non_manifold,
            planarity_tolerance=planarity_tolerance,
            skip_intersection_check=skip_intersection_check,
            threads=threads,
        )
        out = ffi.new("polymass_mesh**")
        raise_for_status(lib.polymass_mesh_create(out, ctx, mesh.desc), ctx)
        self._handle = ffi.gc(out[0], lib.polymass_mesh_destroy)

    def mass_properties(
        self, *, density: float | None = None, mass: float | None = None, about: About = "com"
    ) -> MassProperties:
        """The properties as a body of this density (M/L^3) or mass (M); see `mass_properties`."""
        return _properties(
            lib.polymass_mesh_mass_properties, self._handle, density=density, mass=mass, about=about
        )
