"""`polygon_properties`: area, centroid and second moments of area of a 2D polygon.

Second moments of AREA (L^4) with the engineering sign: Ixx = integral y^2 dA,
Iyy = integral x^2 dA, Ixy = +integral x y dA (not negated, unlike the 3D
inertia tensor).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ._arrays import as_positions, row_stride, rows_buffer
from ._library import context, ffi, lib, new_struct
from .errors import raise_for_status


def _frozen(values, count: int) -> np.ndarray:
    array = np.array(ffi.unpack(values, count), dtype=np.float64)
    array.setflags(write=False)
    return array


# eq=False: arrays have no single truth value, so a field-wise == would raise.
@dataclass(frozen=True, eq=False)
class PolygonProperties:
    """The properties of a simple planar polygon. Arrays are read-only float64.

    area: L^2, positive whatever the orientation.
    counter_clockwise: the orientation the points were given in.
    centroid: (2,), L.
    second_moments: (Ixx, Iyy, Ixy) about the centroid, L^4.
    second_moments_origin: (Ixx, Iyy, Ixy) about (0, 0).
    polar_moment: Ixx + Iyy about the centroid.
    principal_moments: (2,) about the centroid, ascending.
    principal_angle: radians counter-clockwise from +x, in (-pi/2, pi/2], of
        the axis about which the second moment is principal_moments[0].
    """

    area: float
    counter_clockwise: bool
    centroid: np.ndarray
    second_moments: np.ndarray
    second_moments_origin: np.ndarray
    polar_moment: float
    principal_moments: np.ndarray
    principal_angle: float


def polygon_properties(points: npt.ArrayLike) -> PolygonProperties:
    """Area, centroid and second moments of area of a simple polygon.

    points: (n, 2) array of x, y (convex or not, either orientation); the polygon
        closes itself, so do not repeat the first point. float64 rows with
        consecutive x, y are read in place whatever the row stride; other
        inputs are converted to float64. A self-intersecting polygon is not
        detected: its result is the signed sum over its lobes.
    """
    array = as_positions(points, 2, name="points", keep_float32=False)
    result = new_struct("polymass_polygon_properties")
    ctx = context()
    buffer = rows_buffer(array)  # held while the library reads it
    status = lib.polymass_polygon_compute(
        result, ctx, ffi.cast("const double *", buffer), len(array), row_stride(array)
    )
    raise_for_status(status, ctx)
    return PolygonProperties(
        area=result.area,
        counter_clockwise=result.orientation > 0,
        centroid=_frozen(result.centroid, 2),
        second_moments=_frozen(result.second_moments, 3),
        second_moments_origin=_frozen(result.second_moments_origin, 3),
        polar_moment=result.polar_moment,
        principal_moments=_frozen(result.principal_moments, 2),
        principal_angle=result.principal_angle,
    )
