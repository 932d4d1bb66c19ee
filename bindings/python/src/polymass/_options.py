"""The keyword options shared by `Mesh`, `mass_properties` and `check`, as polymass_options."""

from __future__ import annotations

from typing import Union

from . import _header
from ._library import lib, new_struct
from .errors import raise_for_status

# weld: False (no welding), True (exactly equal positions are one vertex) or a
# tolerance relative to the mesh's largest bounding-box extent.
Weld = Union[bool, float]


def apply_options(
    context,
    *,
    weld: Weld = False,
    skip_checks: bool = False,
    accept_inverted: bool = False,
    accept_non_manifold: bool = False,
    planarity_tolerance: float | None = None,
) -> None:
    """Sets the options of this thread's context for the next call through it."""
    options = new_struct("polymass_options")
    flags = 0
    if skip_checks:
        flags |= _header.POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS
    if accept_inverted:
        flags |= _header.POLYMASS_OPTION_ACCEPT_INVERTED
    if accept_non_manifold:
        flags |= _header.POLYMASS_OPTION_ACCEPT_NON_MANIFOLD
    if weld is not False:
        flags |= _header.POLYMASS_OPTION_WELD_VERTICES
        options.weld_tolerance = 0.0 if weld is True else float(weld)
    options.flags = flags
    options.planarity_tolerance = 0.0 if planarity_tolerance is None else planarity_tolerance
    raise_for_status(lib.polymass_context_set_options(context, options), context)
