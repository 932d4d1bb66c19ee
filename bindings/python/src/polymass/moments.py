"""Moments that compose: `moments` and `Moments`.

A `Moments` value holds the mass integrals of a body about its own reference
point, near the body, so that a part far from the origin keeps its digits.
Parts add (``a + b``) and subtract (a bore removed from a block: ``a - b``),
move rigidly (``transformed``), scale and mirror (``scaled``), take a density
or a mass (``weighted``), and become mass properties about any point
(``mass_properties``). The derivations are in docs/moments.md.

    parts = [polymass.moments(v, f).weighted(density=d) for v, f, d in assembly]
    total = sum(parts[1:], parts[0])
    total.mass_properties(about="origin")
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _header
from ._arrays import FacesLike, mesh_description
from ._library import context, ffi, lib, new_struct, working_context
from ._options import Options, c_options, gather
from .errors import raise_for_status
from .solids import About, MassProperties, mass_desc, reference_point


def _call(function, *arguments) -> Moments:
    out = new_struct("polymass_moments")
    ctx = context()
    raise_for_status(function(out, ctx, *arguments), ctx)
    return Moments._wrap(out)


def _rotation_matrix(rotation: npt.ArrayLike | None) -> np.ndarray:
    """A (3, 3) matrix as given, or the matrix of a unit quaternion (w, x, y, z)."""
    if rotation is None:
        return np.eye(3)
    array = np.asarray(rotation, dtype=np.float64)
    if array.shape == (3, 3):
        return array
    if array.shape != (4,):
        raise ValueError(
            "rotation must be a (3, 3) matrix or a quaternion (w, x, y, z); "
            f"got shape {array.shape}"
        )
    norm = np.linalg.norm(array)
    if not np.isfinite(norm) or abs(norm - 1.0) > 1e-9:
        raise ValueError(f"the quaternion {array.tolist()} is not of unit length (|q| = {norm})")
    w, x, y, z = array / norm
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def _vector3(values, name: str) -> list[float]:
    array = np.asarray(values, dtype=np.float64)
    if array.shape != (3,):
        raise ValueError(f"{name} must have 3 elements; got shape {array.shape}")
    return array.tolist()


class Moments:
    """The mass integrals of a body about its reference point: an immutable value.

    reference: (3,) the point the integrals are about.
    volume: the solid's volume, L^3 (a difference may be 0 or negative).
    mass: integral rho dV, M (the volume until a density is applied).
    first: (3,) integral rho r dV, r measured from ``reference``.
    second: (3, 3) integral rho r r^T dV.
    partial: the moments of a range of faces (see `moments`), not yet a body.
    """

    __slots__ = ("_c",)

    @classmethod
    def _wrap(cls, c) -> Moments:
        value = cls.__new__(cls)
        value._c = c
        return value

    @property
    def reference(self) -> np.ndarray:
        return np.array(list(self._c.reference))

    @property
    def volume(self) -> float:
        return float(self._c.volume)

    @property
    def mass(self) -> float:
        return float(self._c.mass)

    @property
    def first(self) -> np.ndarray:
        return np.array(list(self._c.first))

    @property
    def second(self) -> np.ndarray:
        xx, yy, zz, xy, yz, zx = self._c.second
        return np.array([[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]])

    @property
    def partial(self) -> bool:
        return bool(self._c.flags & _header.POLYMASS_MOMENTS_PARTIAL)

    def completed(self) -> Moments:
        """These moments, no longer partial: say so once the ranges of faces added up
        cover the whole closed surface."""
        out = new_struct("polymass_moments")
        ffi.memmove(out, self._c, ffi.sizeof("polymass_moments"))
        out.flags &= ~_header.POLYMASS_MOMENTS_PARTIAL
        return Moments._wrap(out)

    def __add__(self, other: Moments) -> Moments:
        """Two disjoint bodies as one, about this one's reference point."""
        if not isinstance(other, Moments):
            return NotImplemented
        return _call(lib.polymass_moments_add, self._c, other._c)

    def __radd__(self, other: object) -> Moments:
        """``sum(parts)`` starts from 0."""
        if isinstance(other, int) and other == 0:
            return self
        return NotImplemented

    def __sub__(self, other: Moments) -> Moments:
        """``other`` removed from this body (it must lie inside)."""
        if not isinstance(other, Moments):
            return NotImplemented
        return _call(lib.polymass_moments_subtract, self._c, other._c)

    def transformed(
        self, *, rotation: npt.ArrayLike | None = None, translation: npt.ArrayLike | None = None
    ) -> Moments:
        """The body moved by x -> rotation @ x + translation.

        rotation: a (3, 3) orthonormal matrix (determinant -1 mirrors: the result
            is the mirror-image solid, of the same positive volume) or a unit
            quaternion (w, x, y, z); None: no rotation.
        translation: (3,); None: none.
        """
        matrix = _rotation_matrix(rotation)
        shift = ffi.NULL if translation is None else _vector3(translation, "translation")
        return _call(lib.polymass_moments_transform, self._c, matrix.ravel().tolist(), shift)

    def scaled(self, factors: float | Sequence[float]) -> Moments:
        """The body stretched about the origin: one factor, or one per axis (negative
        factors mirror). The density is kept: the mass scales with the volume."""
        if np.ndim(factors) == 0:
            factors = [float(factors)] * 3  # type: ignore[arg-type]
        return _call(lib.polymass_moments_scale, self._c, _vector3(factors, "factors"))

    def weighted(self, *, density: float | None = None, mass: float | None = None) -> Moments:
        """The body made of a material of this density (M/L^3), or of this mass (M):
        the whole mass distribution rescaled to that mean density or total mass."""
        if density is None and mass is None:
            raise ValueError("give a density or a mass")
        return _call(lib.polymass_moments_weight, self._c, mass_desc(density, mass))

    def mass_properties(
        self, *, density: float | None = None, mass: float | None = None, about: About = "com"
    ) -> MassProperties:
        """Mass properties of the body, weighted as by `weighted` when a density or
        mass is given (otherwise as the moments are). ``surface_area`` is NaN:
        moments do not keep the surface."""
        body = ffi.NULL if density is None and mass is None else mass_desc(density, mass)
        point = reference_point(about)
        result = new_struct("polymass_mass_properties")
        ctx = context()
        raise_for_status(lib.polymass_moments_mass_properties(result, ctx, self._c, body), ctx)
        return MassProperties._from_c(result, point)

    def __repr__(self) -> str:
        partial = ", partial" if self.partial else ""
        return (
            f"Moments(volume={self.volume!r}, mass={self.mass!r}, "
            f"reference={self.reference.tolist()!r}{partial})"
        )


def moments(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    face_range: tuple[int, int] | None = None,
    reference: npt.ArrayLike | None = None,
    options: Options | None = None,
    threads: int | None = None,
    **option_fields: Any,
) -> Moments:
    """The moments (unit density) of a closed surface; arguments as `mass_properties`.

    Without ``face_range``: ``Mesh(...).moments``, raising the surface's error.
    face_range: (first, count): only those faces, about ``reference`` (required
        then: the same point for every range of one surface). Indices and
        coordinates are checked, and polygon faces' planarity unless the options
        skip the topology checks; whether the whole is closed is the whole's
        question. The result is ``partial``: ranges add only to each other, and
        their sum, once it covers the whole surface, is made a body with
        `Moments.completed`.
    """
    if face_range is None:
        if reference is not None:
            raise ValueError("reference is for a face_range; a whole surface chooses its own")
        from .mesh import Mesh  # mesh imports this module: import on use

        return Mesh(
            vertices,
            faces,
            face_sizes=face_sizes,
            options=options,
            threads=threads,
            **option_fields,
        ).moments
    if reference is None:
        raise ValueError("a face_range needs a reference point, the same for every range")
    chosen = c_options(gather(options, option_fields))
    description = mesh_description(vertices, faces, face_sizes)
    first, count = face_range
    out = new_struct("polymass_moments")
    ctx = working_context(threads)
    status = lib.polymass_moments_compute_faces(
        out, ctx, description.desc, int(first), int(count), _vector3(reference, "reference"), chosen
    )
    raise_for_status(status, ctx)
    return Moments._wrap(out)
