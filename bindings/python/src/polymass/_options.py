"""`Options`: what one analysis checks and accepts, and how it makes the surface a body.

Every call that analyses a surface (`mass_properties`, `Mesh`, `check`, `moments`,
`batch`) takes an ``options=Options(...)`` and/or the same fields as keywords, which
replace those of ``options``; `gather` makes them one `Options`, and `c_options`
translates it into the polymass_options of that call. Nothing is kept between calls.
"""

from __future__ import annotations

import dataclasses
import numbers
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Union

import numpy as np

from . import _header
from ._library import new_struct

# weld: False (no welding), True (exactly equal positions are one vertex) or a
# tolerance relative to the mesh's largest bounding-box extent.
Weld = Union[bool, float]

# The names of polymass_options.modes, in the order of the header.
_MODES = {
    "solid": _header.POLYMASS_MODE_SOLID,
    "repair": _header.POLYMASS_MODE_REPAIR,
    "shell": _header.POLYMASS_MODE_SHELL,
    "hull": _header.POLYMASS_MODE_HULL,
}


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


def _mode_names(modes: str | Sequence[str]) -> tuple[str, ...]:
    """The chain as a tuple of names: a sequence of names, or one comma-separated string."""
    names = tuple(part.strip() for part in modes.split(",")) if isinstance(modes, str) else modes
    names = tuple(names)
    unknown = [name for name in names if name not in _MODES]
    if unknown:
        raise ValueError(f"modes are {', '.join(map(repr, _MODES))}; got {unknown!r}")
    if not names or len(names) > _header.POLYMASS_MAX_MODES:
        raise ValueError(
            f"modes lists 1 to {_header.POLYMASS_MAX_MODES} modes, tried in order; got {names!r}"
        )
    return names


@dataclass(frozen=True)
class Options:
    """What an analysis checks and accepts, and how it makes the surface a body.

    The defaults are the safe ones: every check that can change the answer, and
    the exact solid alone. Skipping a check or accepting an approximation is
    asked for by name. An immutable value: build it once, pass it to any number
    of calls (``options=``), or give its fields as keywords of the call.

    weld: for triangle soups (STL): True treats vertices at exactly the same
        position as one for the topology checks; a float is a tolerance relative
        to the largest extent of the mesh (at most 1e-3; CAD exports carrying
        rounding noise want about 1e-9). The integrals do not depend on it.
    skip_checks: trusted input: skip the closed, manifold, orientation and
        planarity checks, and the intersection check with them (indices and
        finiteness are always checked); the result carries Warnings.UNCHECKED.
    skip_intersection_check: for trusted input only. By default faces that
        cross each other and shells inside a solid of the same sense (whose
        volume would be counted twice: overlapping parts exported as one file)
        are refused with IntersectingSurfaceError, how shells nest judged
        exactly, and faces that only touch give Warnings.TOUCHING_FACES. True
        skips that check, most of an analysis's time (see the README): two
        overlapping parts then pass with their overlap counted twice, and the
        result carries Warnings.INTERSECTIONS_UNCHECKED. The check never changes
        a result it accepts.
    accept_inverted: a solid whose faces are all reversed gives the properties
        of the solid turned the right way, with Warnings.INVERTED, instead of
        raising InvertedError.
    accept_non_manifold: accept edges shared by more than two faces when they
        are traversed as often one way as the other (solids touching at an edge).
    planarity_tolerance: how far a polygon face's vertex may be off its plane,
        relative to the face's diameter (None: 1e-6).
    modes: how the surface becomes a body, tried in order until one answers:
        "solid" (exact, for a valid closed solid; the default), "repair" (a
        surface that is not a valid solid repaired where the fix is unique:
        orientation, duplicate and two-vertex faces, non-planar polygons,
        holes, balanced non-manifold edges; docs/repair.md), "shell" (a thin
        wall of ``shell_thickness``: mass = density * thickness * area; open
        surfaces are fine), "hull" (the convex hull of the vertices, an upper
        bound). A sequence such as ("solid", "repair", "hull"), or one string
        ("repair" or "solid,repair,hull"). A result's `provenance` says which
        mode answered and what it did, its error_bound how far off it can be.
        A valid solid is answered exactly by "repair" too.
    shell_thickness: the wall's thickness (L) of the "shell" mode: given when,
        and only when, the modes hold "shell".
    """

    weld: Weld = False
    skip_checks: bool = False
    skip_intersection_check: bool = False
    accept_inverted: bool = False
    accept_non_manifold: bool = False
    planarity_tolerance: float | None = None
    modes: tuple[str, ...] = ("solid",)
    shell_thickness: float | None = None

    def __post_init__(self) -> None:
        _weld_tolerance(self.weld)
        # Frozen: the normalised chain is written the way dataclasses do it.
        object.__setattr__(self, "modes", _mode_names(self.modes))
        if ("shell" in self.modes) != (self.shell_thickness is not None):
            raise ValueError(
                'the "shell" mode wants its thickness: shell_thickness=T with modes holding '
                '"shell" (and only then)'
            )


_FIELDS = tuple(field.name for field in dataclasses.fields(Options))


def gather(options: Options | None, keywords: dict[str, Any]) -> Options:
    """The options of one call: ``options`` (None: the defaults) with the fields
    given as keywords replacing its own."""
    unknown = sorted(keywords.keys() - set(_FIELDS))
    if unknown:
        raise TypeError(
            f"unknown option {', '.join(unknown)}; the options are {', '.join(_FIELDS)}"
        )
    if options is None:
        return Options(**keywords)
    if not isinstance(options, Options):
        raise TypeError(f"options must be a polymass.Options; got {type(options).__name__}")
    return dataclasses.replace(options, **keywords) if keywords else options


def c_options(options: Options):
    """``options`` as the polymass_options of one call."""
    c = new_struct("polymass_options")
    chain = [_MODES[name] for name in options.modes]
    c.modes = chain + [_header.POLYMASS_MODE_NONE] * (_header.POLYMASS_MAX_MODES - len(chain))
    c.shell_thickness = 0.0 if options.shell_thickness is None else options.shell_thickness
    c.planarity_tolerance = (
        0.0 if options.planarity_tolerance is None else options.planarity_tolerance
    )
    flags = 0
    if options.skip_checks:
        flags |= _header.POLYMASS_OPTION_SKIP_TOPOLOGY_CHECKS
    if options.skip_intersection_check:
        flags |= _header.POLYMASS_OPTION_SKIP_INTERSECTION_CHECK
    if options.accept_inverted:
        flags |= _header.POLYMASS_OPTION_ACCEPT_INVERTED
    if options.accept_non_manifold:
        flags |= _header.POLYMASS_OPTION_ACCEPT_NON_MANIFOLD
    tolerance = _weld_tolerance(options.weld)
    if tolerance is not None:
        flags |= _header.POLYMASS_OPTION_WELD_VERTICES
        c.weld_tolerance = tolerance
    c.flags = flags
    return c
