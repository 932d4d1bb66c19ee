"""Many meshes in one call: `batch`.

Each item gets its own result or its own error; one item's failure does not
stop the others. Results are bit for bit those of `mass_properties`, whatever
the number of threads (the context's: polymass_context_set_threads).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ._arrays import mesh_description
from ._library import ffi, lib, new_struct, working_context
from ._options import Options, c_options, gather
from .errors import Error, error_class, raise_for_status
from .solids import About, MassProperties, Provenance, mass_desc, reference_point


def _per_item(value, count: int, name: str) -> list:
    """A value for every item: one for all, or a sequence of ``count``."""
    if value is None or np.ndim(value) == 0:
        return [value] * count
    values = list(value)
    if len(values) != count:
        raise ValueError(f"{name} has {len(values)} values for {count} meshes")
    return values


def _compute(
    pending: list, options, point: np.ndarray | None, threads: int | None
) -> list[tuple[int, MassProperties | Error]]:
    """One ``polymass_batch_compute`` call over pending items on this thread's
    context, spread over ``threads`` of the library's threads: each item's
    position and its result or error."""
    items = ffi.new("polymass_batch_item[]", len(pending))
    for item, (_, description, body, result, provenance) in zip(items, pending):
        item.struct_size = ffi.sizeof("polymass_batch_item")
        item.desc = description.desc
        item.options = options
        item.mass = body
        item.properties = result
        item.provenance = provenance
    ctx = working_context(threads)  # the context's threads spread the items
    failed = ffi.new("uint64_t*")
    raise_for_status(lib.polymass_batch_compute(items, len(pending), failed, ctx), ctx)
    outcomes: list[tuple[int, MassProperties | Error]] = []
    for item, (i, _, _, result, provenance) in zip(items, pending):
        if item.status == 0:
            outcomes.append(
                (i, MassProperties._from_c(result, point, Provenance._from_c(provenance)))
            )
        else:
            message = ffi.string(item.message).decode("utf-8", "replace")
            outcomes.append((i, error_class(item.status)(message, item.status)))
    return outcomes


def batch(
    meshes: Sequence[tuple[Any, ...]],
    *,
    density: float | Sequence[float] | None = None,
    mass: float | Sequence[float] | None = None,
    about: About = "com",
    options: Options | None = None,
    threads: int | None = None,
    **option_fields: Any,
) -> list[MassProperties | Error]:
    """The mass properties of many meshes in one call, in order.

    meshes: ``(vertices, faces)`` or ``(vertices, faces, face_sizes)`` tuples, as
        `mass_properties` takes them.
    density, mass: one for every mesh, or a sequence with one per mesh (not both).
    options (and its fields as keywords): as `mass_properties`'s, for every mesh.
    threads: how many threads compute the meshes (None: one): the library's own
        workers take the meshes one by one in a single
        ``polymass_batch_compute`` call, the GIL released during it. Each
        mesh's result does not depend on the others, so the results are those
        of ``threads=1``.

    Returns a list with, for each mesh, its `MassProperties` (with its
    provenance) or the `polymass.Error` (an instance of the subclass for its
    status, not raised) that says what is wrong with it. Arguments that cannot
    describe a mesh at all (a ragged array) raise at once. The GIL is released
    while the library computes.
    """
    count = len(meshes)
    densities = _per_item(density, count, "density")
    masses = _per_item(mass, count, "mass")
    chosen = c_options(gather(options, option_fields))
    point = reference_point(about)
    results: list[MassProperties | Error | None] = [None] * count
    pending = []  # (position, description, mass desc, result, provenance): what items point into
    for i, mesh in enumerate(meshes):
        try:  # an index the binding itself checks fails this mesh alone
            description = mesh_description(mesh[0], mesh[1], mesh[2] if len(mesh) > 2 else None)
        except Error as error:
            results[i] = error
            continue
        body = mass_desc(densities[i], masses[i])
        outputs = new_struct("polymass_mass_properties"), new_struct("polymass_provenance")
        pending.append((i, description, body, *outputs))
    if pending:
        for i, outcome in _compute(pending, chosen, point, threads):
            results[i] = outcome
    return results  # type: ignore[return-value]
