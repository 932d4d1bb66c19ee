"""Mass properties of closed polyhedral surfaces: `mass_properties`, one call, and
what it returns (`MassProperties`, `Provenance`, `Warnings`).

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
from typing import Any, Literal, Union

import numpy as np
import numpy.typing as npt

from . import _header
from ._arrays import FacesLike, mesh_description
from ._library import ffi, lib, new_struct, working_context
from ._options import Options, c_options, gather
from .errors import error_class, raise_for_status

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
    INTERSECTIONS_UNCHECKED = _header.POLYMASS_WARNING_INTERSECTIONS_UNCHECKED
    """The intersection check did not run (skip_intersection_check=True, or
    skip_checks=True): overlapping parts would have been counted twice."""
    NON_MANIFOLD = _header.POLYMASS_WARNING_NON_MANIFOLD
    """Non-manifold edges were accepted (accept_non_manifold=True)."""
    TOUCHING_FACES = _header.POLYMASS_WARNING_TOUCHING_FACES
    """Faces touch without crossing, such as parts resting on each other: found by
    the intersection check (on by default), and `check` lists the face pairs."""
    REPAIRED = _header.POLYMASS_WARNING_REPAIRED
    """Not a valid solid: the surface was repaired (see `Provenance`)."""
    SHELL = _header.POLYMASS_WARNING_SHELL
    """Computed as a thin wall (the "shell" mode), not as a solid."""
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
    """How the answer was reached: which of the `Options.modes` answered, and what it did.

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
    def _from_c(
        cls, result, point: np.ndarray | None, provenance: Provenance | None = None
    ) -> MassProperties:
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
            inertia_point=inertia if point is None else _inertia_about(result, point),
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
            provenance=Provenance() if provenance is None else provenance,
        )


def _inertia_about(result, point: np.ndarray) -> np.ndarray:
    """The inertia tensor of a polymass_mass_properties about ``point``."""
    out = ffi.new("double[9]")
    status = lib.polymass_inertia_about(out, result, point.tolist())
    if status != _header.POLYMASS_OK:
        raise error_class(status)(f"the inertia about the point {point.tolist()}", status)
    return _frozen(out, (3, 3))


def mass_desc(density: float | None, mass: float | None):
    """The polymass_mass_desc of a body of this density or mass (neither: density 1)."""
    if density is not None and mass is not None:
        raise ValueError("give density or mass, not both")
    desc = new_struct("polymass_mass_desc")
    if mass is not None:
        desc.mass_mode = _header.POLYMASS_MASS_FROM_TOTAL
        desc.mass = mass
    else:
        desc.mass_mode = _header.POLYMASS_MASS_FROM_DENSITY
        desc.density = 1.0 if density is None else density
    return desc


def reference_point(about: About) -> np.ndarray | None:
    """The point of ``inertia_point`` (read-only), or None for the centre of mass."""
    if isinstance(about, str):
        if about == "com":
            return None
        if about != "origin":
            raise ValueError(f'about must be "com", "origin" or a point (x, y, z); got {about!r}')
        point = np.zeros(3)
    else:
        point = np.array(about, dtype=np.float64)
        if point.shape != (3,):
            raise ValueError(f"about must be a point (x, y, z); got shape {point.shape}")
    point.setflags(write=False)
    return point


def mass_properties(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    density: float | None = None,
    mass: float | None = None,
    about: About = "com",
    options: Options | None = None,
    threads: int | None = None,
    **option_fields: Any,
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
    options: an `Options` (None: the defaults: every check, the exact solid);
        its fields may also be given as keywords (``weld=True``,
        ``skip_intersection_check=True``, ``modes=("solid", "repair")``, ...),
        which replace those of ``options``.
    threads: how many threads the library may use for the call (None: one);
        every count gives the same bits.

    The one-call path: the analysis `Mesh` makes, stopping at the first defect,
    with no mesh left. Returns a `MassProperties`; raises a subclass of
    `polymass.Error` saying what is wrong and where. The GIL is released while
    the library computes.
    """
    chosen = c_options(gather(options, option_fields))
    description = mesh_description(vertices, faces, face_sizes)
    body, point = mass_desc(density, mass), reference_point(about)
    result = new_struct("polymass_mass_properties")
    provenance = new_struct("polymass_provenance")
    ctx = working_context(threads)
    raise_for_status(
        lib.polymass_mass_properties_compute(
            result, provenance, ctx, description.desc, chosen, body
        ),
        ctx,
    )
    return MassProperties._from_c(result, point, Provenance._from_c(provenance))
