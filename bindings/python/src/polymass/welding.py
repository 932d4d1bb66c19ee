"""`weld`: the library's welding over positions alone, for a caller that numbers
vertices itself (a triangle soup such as an STL repeats a vertex once per face)."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from ._arrays import as_positions, position_type, row_stride, rows_buffer
from ._library import context, ffi, lib
from .errors import raise_for_status


class Welded(NamedTuple):
    """What `weld` found."""

    vertex_of: np.ndarray
    """For each vertex, the lowest vertex index welded to it (uint32, read-only):
    ``vertex_of[faces]`` numbers a soup's faces by distinct positions."""
    distinct_count: int
    """How many vertices are their own lowest: the distinct positions."""


def weld(vertices: npt.ArrayLike, *, tolerance: float = 0.0) -> Welded:
    """Which vertices are one: those at the same position, or within ``tolerance``.

    vertices: (n, 3) float64 or float32, read in place as `mass_properties`
        reads them.
    tolerance: relative to the largest extent of the positions' bounding box,
        at most 1e-3: 0 (the default) welds exactly equal positions (+0 and -0
        being one, and copies of the same NaN) in one hashing pass; above 0,
        chains of near positions are one, and non-finite coordinates raise
        NonFiniteError. The rule `Options.weld` applies to an analysis.
    """
    positions = as_positions(vertices, 3, name="vertices")
    vertex_of = np.empty(len(positions), dtype=np.uint32)
    distinct = ffi.new("uint64_t *")
    ctx = context()
    status = lib.polymass_weld_positions(
        ffi.from_buffer("uint32_t[]", vertex_of, require_writable=True),
        distinct,
        ctx,
        rows_buffer(positions),
        position_type(positions),
        len(positions),
        row_stride(positions),
        tolerance,
    )
    raise_for_status(status, ctx)
    vertex_of.setflags(write=False)
    return Welded(vertex_of, int(distinct[0]))
