"""Exceptions: one class per status of the C library, all subclasses of `Error`.

Each carries the status code (``status``), the library's name for it
(``status_name``) and the detailed message the library kept in the context
(``message``: what and where, such as "edge (4, 9) is used by 3 faces").
"""

from __future__ import annotations

from . import _header
from ._library import ffi, lib


class Error(Exception):
    """Any failure reported by libpolymass."""

    status: int = -1

    def __init__(self, message: str, status: int | None = None) -> None:
        if status is not None:
            self.status = status
        self.status_name = ffi.string(lib.polymass_status_string(self.status)).decode()
        self.message = message
        super().__init__(f"{self.status_name}: {message}" if message else self.status_name)


class InvalidArgumentError(Error, ValueError):
    """An argument the library cannot use (a stride, a count, an option out of range)."""

    status = _header.POLYMASS_ERROR_INVALID_ARGUMENT


class OutOfMemoryError(Error, MemoryError):
    """The library could not allocate memory."""

    status = _header.POLYMASS_ERROR_OUT_OF_MEMORY


class InternalError(Error):
    """A bug in libpolymass: please report it with the message."""

    status = _header.POLYMASS_ERROR_INTERNAL


class NonFiniteError(Error, ValueError):
    """A coordinate used by a face is NaN or infinite."""

    status = _header.POLYMASS_ERROR_NON_FINITE


class IndexOutOfRangeError(Error, IndexError):
    """A face refers to a vertex that does not exist."""

    status = _header.POLYMASS_ERROR_INDEX_OUT_OF_RANGE


class FaceTooSmallError(Error, ValueError):
    """A face (or a 2D polygon) has fewer than 3 vertices."""

    status = _header.POLYMASS_ERROR_FACE_TOO_SMALL


class TopologyError(Error, ValueError):
    """The surface is not the boundary of a solid: the base of the four cases below."""


class OpenSurfaceError(TopologyError):
    """An edge is used by one face only: the surface has a hole."""

    status = _header.POLYMASS_ERROR_OPEN


class NonManifoldError(TopologyError):
    """An edge is used by more than two faces."""

    status = _header.POLYMASS_ERROR_NON_MANIFOLD


class InconsistentOrientationError(TopologyError):
    """Two faces traverse an edge the same way: one of them is flipped."""

    status = _header.POLYMASS_ERROR_INCONSISTENT_ORIENTATION


class NonPlanarFaceError(TopologyError):
    """A polygon face is off its plane by more than the planarity tolerance."""

    status = _header.POLYMASS_ERROR_NON_PLANAR_FACE


class IntersectingSurfaceError(Error, ValueError):
    """Faces cross each other (or lie on another shell's faces, facing the same way), or a shell
    lies inside a solid of the same sense or passes through another's surface: some region would
    be counted twice (overlapping parts, a surface written twice, a surface folded through
    itself). Found by default (not with ``skip_intersection_check=True`` or ``skip_checks=True``);
    the message names a pair of faces (or the shell)."""

    status = _header.POLYMASS_ERROR_INTERSECTING


class InvertedError(Error, ValueError):
    """Every face is reversed (negative volume), or one shell is inside out while lying inside
    no solid shell; see ``accept_inverted``."""

    status = _header.POLYMASS_ERROR_INVERTED


class ZeroVolumeError(Error, ValueError):
    """The surface encloses no volume (to rounding)."""

    status = _header.POLYMASS_ERROR_ZERO_VOLUME


class ZeroAreaError(Error, ValueError):
    """A 2D polygon encloses no area (to rounding)."""

    status = _header.POLYMASS_ERROR_ZERO_AREA


class ResultOutOfRangeError(Error, ArithmeticError):
    """A result does not fit in a double: coordinates, density, mass or point too large or small."""

    status = _header.POLYMASS_ERROR_OVERFLOW


_BY_STATUS: dict[int, type[Error]] = {
    cls.status: cls
    for cls in (
        InvalidArgumentError,
        OutOfMemoryError,
        InternalError,
        NonFiniteError,
        IndexOutOfRangeError,
        FaceTooSmallError,
        OpenSurfaceError,
        NonManifoldError,
        InconsistentOrientationError,
        NonPlanarFaceError,
        IntersectingSurfaceError,
        InvertedError,
        ZeroVolumeError,
        ZeroAreaError,
        ResultOutOfRangeError,
    )
}


def error_class(status: int) -> type[Error]:
    """The exception class of a status (`Error` itself for a status this binding predates)."""
    return _BY_STATUS.get(status, Error)


class Verdict:
    """What an analysis concluded: ``status``, 0 (POLYMASS_OK) when a mode of the
    options' chain answered, else an error status; and the library's ``message``
    saying what is wrong with the surface as given, and where ("" for a valid
    solid; kept when a later mode answered, then followed by each later mode's
    reason when none did)."""

    status: int
    message: str

    @property
    def ok(self) -> bool:
        """Whether the analysis gave an answer."""
        return self.status == _header.POLYMASS_OK

    @property
    def error(self) -> type[Error] | None:
        """The exception class of the status, or None when OK."""
        return None if self.ok else error_class(self.status)

    def raise_if_error(self) -> None:
        """Raises the exception of the status, with the message, unless OK."""
        if not self.ok:
            raise error_class(self.status)(self.message, self.status)


def raise_for_status(status: int, context) -> None:
    """Raises the exception of a failed call, with the message ``context`` holds."""
    if status == _header.POLYMASS_OK:
        return
    message = ffi.string(lib.polymass_context_message(context)).decode() if context else ""
    raise error_class(status)(message, status)
