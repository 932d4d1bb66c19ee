"""The keyword options of `Mesh`, `mass_properties`, `moments` and `check`: polymass_options."""

from __future__ import annotations

import numbers
from typing import Union

import numpy as np

from . import _header
from ._library import lib, new_struct
from .errors import raise_for_status

# weld: False (no welding), True (exactly equal positions are one vertex) or a
# tolerance relative to the mesh's largest bounding-box extent.
Weld = Union[bool, float]


def _weld_tolerance(weld: Weld) -> float | None:
    """None for no welding, else the relative tolerance (0.0: exact positions).

    Booleans (NumPy's too) switch welding; a float is a tolerance, which the
    library checks. An integer is refused: ``weld=0`` could mean either."""
    if isinstance(weld, (bool, np.bool_)):
        return 0.0 if weld else None
    if isinstance(weld, numbers.Real) and not isinstance(weld, numbers.Integral):
        return float(weld)
    raise TypeError(
        "weld must be False, True (exact positions) or a float tolerance relative to the "
        f"mesh's extent, such as 1e-9; got {weld!r}"
    )


def apply_options(context, **keywords) -> None:
    """Sets the options of this thread's context for the next call through it."""
    raise_for_status(lib.polymass_context_set_options(context, call_options(**keywords)), context)


def call_options(
    *,
    weld: Weld = False,
    skip_checks: bool = False,
    accept_inverted: bool = False,
    accept_non_manifold: bool = False,
    planarity_tolerance: float | None = None,
    check_intersections: bool = False,
):
    """The keywords as a polymass_options, for a call that takes its own options."""
    options = new_struct("polymass_options")
    flags = 0
    if skip_checks:
        flags |= _header.POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS
    if accept_inverted:
        flags |= _header.POLYMASS_OPTION_ACCEPT_INVERTED
    if accept_non_manifold:
        flags |= _header.POLYMASS_OPTION_ACCEPT_NON_MANIFOLD
    if check_intersections:
        flags |= _header.POLYMASS_OPTION_CHECK_INTERSECTIONS
    if _weld_tolerance(weld) is not None:
        flags |= _header.POLYMASS_OPTION_WELD_VERTICES
        options.weld_tolerance = _weld_tolerance(weld)
    options.flags = flags
    options.planarity_tolerance = 0.0 if planarity_tolerance is None else planarity_tolerance
    return options
