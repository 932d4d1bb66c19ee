"""The keyword options of `Mesh`, `mass_properties`, `moments` and `check`: polymass_options."""

from __future__ import annotations

import numbers
from collections.abc import Sequence
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


def _threads(threads: int | None) -> int:
    """polymass_options.threads: None (the library's default, one thread) or a
    positive integer, which the library bounds."""
    if threads is None:
        return 0
    if (
        isinstance(threads, (bool, np.bool_))
        or not isinstance(threads, numbers.Integral)
        or threads < 1
    ):
        raise ValueError(f"threads must be a positive integer (or None), not {threads!r}")
    # Beyond uint32_t the library's own check would never see the value.
    return min(int(threads), 2**32 - 1)


_MODES = {
    "repair": _header.POLYMASS_MODE_REPAIR,
    "shell": _header.POLYMASS_MODE_SHELL,
    "hull": _header.POLYMASS_MODE_HULL,
}


def _modes(repair: bool, shell: float | None, hull: bool, fallback: Sequence[str]) -> list[int]:
    """The chain of modes the keywords ask for (POLYMASS_MODE_* values).

    repair, shell (a thickness) and hull each choose one mode; fallback is a
    list of "repair", "shell" (with shell=thickness) and "hull" tried in order
    after the solid."""
    if isinstance(fallback, str):
        fallback = [part for part in fallback.split(",") if part]
    chosen = bool(repair) + (shell is not None) + bool(hull)
    if fallback:
        if repair or hull:
            raise ValueError("give repair, shell, hull, or fallback with a list of them")
        unknown = [name for name in fallback if name not in _MODES]
        if unknown:
            raise ValueError(
                f'fallback lists modes from "repair", "shell", "hull"; got {unknown!r}'
            )
        if ("shell" in fallback) != (shell is not None):
            raise ValueError("a shell in the fallback wants its thickness: shell=T (and only then)")
        chain = [_header.POLYMASS_MODE_SOLID]
        for name in fallback:
            if _MODES[name] not in chain:
                chain.append(_MODES[name])
        return chain
    if chosen > 1:
        raise ValueError("give repair, shell, hull, or fallback with a list of them")
    if repair:
        return [_header.POLYMASS_MODE_REPAIR]
    if shell is not None:
        return [_header.POLYMASS_MODE_SHELL]
    if hull:
        return [_header.POLYMASS_MODE_HULL]
    return [_header.POLYMASS_MODE_SOLID]


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
    skip_intersection_check: bool = False,
    repair: bool = False,
    shell: float | None = None,
    hull: bool = False,
    fallback: Sequence[str] = (),
    threads: int | None = None,
):
    """The keywords as a polymass_options, for a call that takes its own options."""
    options = new_struct("polymass_options")
    options.threads = _threads(threads)
    chain = _modes(repair, shell, hull, fallback)
    options.modes = chain + [_header.POLYMASS_MODE_NONE] * (_header.POLYMASS_MAX_MODES - len(chain))
    options.shell_thickness = 0.0 if shell is None else shell
    flags = 0
    if skip_checks:
        flags |= _header.POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS
    if accept_inverted:
        flags |= _header.POLYMASS_OPTION_ACCEPT_INVERTED
    if accept_non_manifold:
        flags |= _header.POLYMASS_OPTION_ACCEPT_NON_MANIFOLD
    if skip_intersection_check:
        flags |= _header.POLYMASS_OPTION_SKIP_INTERSECTION_CHECK
    if _weld_tolerance(weld) is not None:
        flags |= _header.POLYMASS_OPTION_WELD_VERTICES
        options.weld_tolerance = _weld_tolerance(weld)
    options.flags = flags
    options.planarity_tolerance = 0.0 if planarity_tolerance is None else planarity_tolerance
    return options
