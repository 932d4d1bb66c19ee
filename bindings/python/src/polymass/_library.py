"""Opens libpolymass and checks that it is the library this binding was built for.

Which library (the first that applies):

1. the environment variable ``POLYMASS_LIBRARY``: a path (an installed or locally
   built ``libpolymass.so.2``), or a bare file name such as ``libpolymass.so.2``,
   which the loader looks up in its search path (``ldconfig``, ``LD_LIBRARY_PATH``):
   the system's library, e.g. from the ``libpolymass2`` package;
2. the copy the wheel carries beside this module, built from the same sources as the
   header the declarations come from.

cffi's ABI mode calls it with the GIL released, so threads compute in parallel.
"""

from __future__ import annotations

import numbers
import os
import sys
import threading
from pathlib import Path

import numpy as np

from . import _header
from ._polymass_cffi import ffi

LIBRARY_VARIABLE = "POLYMASS_LIBRARY"


def _soname() -> str:
    major = _header.POLYMASS_VERSION_MAJOR
    if sys.platform == "darwin":
        return f"libpolymass.{major}.dylib"
    if sys.platform == "win32":
        return "polymass.dll"
    return f"libpolymass.so.{major}"


def _open():
    """The library and where it came from (for messages)."""
    soname = _soname()
    requested = os.environ.get(LIBRARY_VARIABLE)
    if requested:
        source = f"{LIBRARY_VARIABLE}={requested}"
        target = requested
    else:
        target = str(Path(__file__).with_name(soname))
        source = f"the copy in the package, {target}"
    try:
        return ffi.dlopen(target), source
    except OSError as error:
        raise ImportError(
            f"polymass: cannot load the C library from {source}: {error}. Set "
            f"{LIBRARY_VARIABLE} to the path of a {soname} (or to {soname} to use the one the "
            "loader finds), or reinstall the package."
        ) from error


def _check_version(library) -> None:
    built = _header.POLYMASS_VERSION_NUMBER
    loaded = library.polymass_version()
    loaded_text = ffi.string(library.polymass_version_string()).decode()
    if loaded // 10000 != built // 10000 or loaded < built:
        raise ImportError(
            f"polymass: the loaded C library is version {loaded_text}; this binding was built "
            f"against {_header.POLYMASS_VERSION_STRING} and needs {built // 10000}.x, at least "
            f"{_header.POLYMASS_VERSION_STRING} (set {LIBRARY_VARIABLE} to choose the library)"
        )


def _check_struct_sizes(library) -> None:
    """Every public struct as the library was compiled must match this binding's layout.

    A newer library of the same major version may have longer structs (fields are
    only appended) and still accepts the older size in struct_size.
    """
    same_version = library.polymass_version() == _header.POLYMASS_VERSION_NUMBER
    prefix = "polymass_sizeof_"
    for function in sorted(name for name in dir(library) if name.startswith(prefix)):
        struct = "polymass_" + function[len(prefix) :]
        try:
            theirs = getattr(library, function)()
        except (AttributeError, ffi.error) as error:
            raise ImportError(
                f"polymass: the loaded library has no {function}: it is not a build of the "
                "header this binding was built from"
            ) from error
        ours = ffi.sizeof(struct)
        if theirs < ours or (same_version and theirs != ours):
            raise ImportError(
                f"polymass: {struct} is {theirs} bytes in the loaded library and {ours} in this "
                "binding: the library and the header the binding was built from disagree"
            )


lib, source = _open()
_check_version(lib)
_check_struct_sizes(lib)

_thread_state = threading.local()


def context():
    """This thread's context: a context is used by one thread at a time."""
    current = getattr(_thread_state, "context", None)
    if current is None:
        from .errors import raise_for_status  # errors imports this module: import on use

        out = ffi.new("polymass_context**")
        raise_for_status(lib.polymass_context_create(out, ffi.NULL), None)
        current = ffi.gc(out[0], lib.polymass_context_destroy)
        _thread_state.context = current
        _thread_state.threads = 1
    return current


def _thread_count(threads: int | None) -> int:
    """The ``threads`` of a call: None (one thread) or a positive integer, which the
    library bounds."""
    if threads is None:
        return 1
    if (
        isinstance(threads, (bool, np.bool_))
        or not isinstance(threads, numbers.Integral)
        or threads < 1
    ):
        raise ValueError(f"threads must be a positive integer (or None), not {threads!r}")
    # Beyond uint32_t the library's own check would never see the value.
    return min(int(threads), 2**32 - 1)


def working_context(threads: int | None):
    """This thread's context, set to use ``threads`` threads (None: one) for the
    calls that analyse a surface. The context keeps its workers while the count
    stays the same, so it is set only when it changes."""
    count = _thread_count(threads)
    current = context()
    if _thread_state.threads != count:
        from .errors import raise_for_status

        raise_for_status(lib.polymass_context_set_threads(current, count), current)
        _thread_state.threads = count
    return current


def new_struct(name: str):
    """A zeroed ``name`` with its struct_size set, as every call expects."""
    value = ffi.new(name + "*")
    value.struct_size = ffi.sizeof(name)
    return value
