"""`Mesh`: one analysis of a surface, and every question answered from it; `check`."""

from __future__ import annotations

from functools import cached_property
from typing import Any

import numpy as np
import numpy.typing as npt

from ._arrays import FacesLike, mesh_description
from ._library import context, ffi, lib, new_struct, working_context
from ._options import Options, c_options, gather
from .diagnostics import Diagnostics, Shell, diagnostics_from_c, shells_from_c
from .errors import Verdict, raise_for_status
from .moments import Moments
from .solids import About, MassProperties, Provenance, mass_desc, reference_point


class Mesh(Verdict):
    """One analysis of a surface, made once; every question after it is a cheap read.

    ``Mesh(vertices, faces, ...)`` takes the arguments of `mass_properties` that
    describe the surface and how it is analysed (``options`` and its fields as
    keywords, ``threads``). The analysis runs every check the options do not
    skip to its end (every finding, not only the first), then the options'
    modes. It keeps what the questions need, not the arrays.

    Whether a mode answered: ``status``, ``message``, ``ok``, ``error``,
    ``raise_if_error()``; a surface that is refused is still a Mesh, so that
    what is wrong can be read from it (``diagnostics``, ``shells``). Only
    arguments that describe no analysis at all raise here (InvalidArgumentError,
    an index the binding cannot convert, out of memory).

    options: the `Options` of the analysis.
    diagnostics: every finding (`Diagnostics`).
    shells: what each shell is (a list of `Shell`).
    shell_of_face: the shell of each face (uint32, read-only), numbered as
        ``shells``; each shell can then be checked or computed on its own.
    provenance, moments, mass_properties(): the body that answered; they raise
        the mesh's error when no mode answered.

    Immutable; any number of threads may read it at once. Freed by the garbage
    collector.
    """

    def __init__(
        self,
        vertices: npt.ArrayLike,
        faces: FacesLike,
        *,
        face_sizes: npt.ArrayLike | None = None,
        options: Options | None = None,
        threads: int | None = None,
        **option_fields: Any,
    ) -> None:
        self.options = gather(options, option_fields)
        description = mesh_description(vertices, faces, face_sizes)
        ctx = working_context(threads)
        out = ffi.new("polymass_mesh **")
        status = lib.polymass_mesh_create(out, ctx, description.desc, c_options(self.options))
        if out[0] == ffi.NULL:  # no analysis: the call itself failed
            raise_for_status(status, ctx)
        self._handle = ffi.gc(out[0], lib.polymass_mesh_destroy)
        self.status = int(lib.polymass_mesh_status(self._handle))
        self.message = ffi.string(lib.polymass_mesh_message(self._handle)).decode()

    @cached_property
    def diagnostics(self) -> Diagnostics:
        """What the analysis found."""
        report = new_struct("polymass_diagnostics")
        ctx = context()
        self._raise_for(lib.polymass_mesh_diagnostics(report, ctx, self._handle), ctx)
        return diagnostics_from_c(report, self.status, self.message)

    @cached_property
    def shells(self) -> list[Shell]:
        """What each shell is; shell i is the one `shell_of_face` numbers i."""
        count = self.diagnostics.shell_count
        described = ffi.new("polymass_shell[]", count)
        for shell in described:
            shell.struct_size = ffi.sizeof("polymass_shell")
        written = ffi.new("uint64_t *")
        ctx = context()
        self._raise_for(lib.polymass_mesh_shells(described, count, written, ctx, self._handle), ctx)
        return shells_from_c(described[0 : min(count, written[0])])

    @cached_property
    def shell_of_face(self) -> np.ndarray:
        """The shell of each face, numbered in the order of the shells' first faces.
        Raises the mesh's error when its faces are unreadable (non-finite
        coordinates, indices out of range, faces of fewer than 3 vertices)."""
        of_face = np.empty(self.diagnostics.face_count, dtype=np.uint32)
        out = ffi.from_buffer("uint32_t[]", of_face, require_writable=True)
        ctx = context()
        self._raise_for(lib.polymass_mesh_shell_of_face(out, of_face.size, ctx, self._handle), ctx)
        of_face.setflags(write=False)
        return of_face

    @cached_property
    def provenance(self) -> Provenance:
        """Which mode answered and what it did."""
        provenance = new_struct("polymass_provenance")
        ctx = context()
        self._raise_for(lib.polymass_mesh_provenance(provenance, ctx, self._handle), ctx)
        return Provenance._from_c(provenance)

    @cached_property
    def moments(self) -> Moments:
        """The moments (unit density) of the body that answered."""
        out = new_struct("polymass_moments")
        ctx = context()
        self._raise_for(lib.polymass_mesh_moments(out, ctx, self._handle), ctx)
        return Moments._wrap(out)

    def mass_properties(
        self, *, density: float | None = None, mass: float | None = None, about: About = "com"
    ) -> MassProperties:
        """The body that answered, of this density (M/L^3) or mass (M), with its
        inertia about ``about`` too; see `mass_properties`."""
        body, point = mass_desc(density, mass), reference_point(about)
        result = new_struct("polymass_mass_properties")
        ctx = context()
        self._raise_for(lib.polymass_mesh_mass_properties(result, ctx, self._handle, body), ctx)
        return MassProperties._from_c(result, point, self.provenance)

    def _raise_for(self, status: int, ctx) -> None:
        """Raises what a getter returned: the mesh's own error, with the mesh's
        message, or one of the call (with the context's)."""
        if status != 0 and status == self.status:
            self.raise_if_error()
        raise_for_status(status, ctx)

    def __repr__(self) -> str:
        verdict = "ok" if self.ok else f"{self.error.__name__}: {self.message}"
        return f"<polymass.Mesh of {self.diagnostics.face_count} faces, {verdict}>"


def check(
    vertices: npt.ArrayLike,
    faces: FacesLike,
    *,
    face_sizes: npt.ArrayLike | None = None,
    options: Options | None = None,
    threads: int | None = None,
    **option_fields: Any,
) -> Diagnostics:
    """Every finding about a surface, instead of the first one as an exception:
    ``Mesh(...).diagnostics``, with the arguments of `Mesh`.

    Problems with the mesh are reported in the result (``status``, ``message``,
    ``ok``, ``error``, ``raise_if_error()``: what `mass_properties` with the same
    options would do), not raised; problems with the call itself
    (InvalidArgumentError, OutOfMemoryError) are raised.
    """
    return Mesh(
        vertices, faces, face_sizes=face_sizes, options=options, threads=threads, **option_fields
    ).diagnostics
