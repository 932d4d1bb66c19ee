"""Opens libpolymass and checks that it is the library this binding was built for.

The library is opened by its SONAME (``libpolymass.so.1``: the loader's search
path, ``ldconfig``, ``LD_LIBRARY_PATH``), or from the path in the environment
variable ``POLYMASS_LIBRARY``. cffi's ABI mode calls it with the GIL released,
so threads compute in parallel.
"""

from __future__ import annotations

import os
import sys
import threading

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
    soname = _soname()
    path = os.environ.get(LIBRARY_VARIABLE)
    try:
        return ffi.dlopen(path or soname)
    except OSError as error:
        tried = f"{LIBRARY_VARIABLE}={path}" if path else f"{soname} (by SONAME)"
        raise ImportError(
            f"polymass: cannot load the C library from {tried}: {error}. Install libpolymass "
            f"so that the loader finds {soname}, or set {LIBRARY_VARIABLE} to the path of "
            f"{soname}."
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
        ours, theirs = ffi.sizeof(struct), getattr(library, function)()
        if theirs < ours or (same_version and theirs != ours):
            raise ImportError(
                f"polymass: {struct} is {theirs} bytes in the loaded library and {ours} in this "
                "binding: the library and the header the binding was built from disagree"
            )


lib = _open()
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
    return current


def new_struct(name: str):
    """A zeroed ``name`` with its struct_size set, as every call expects."""
    value = ffi.new(name + "*")
    value.struct_size = ffi.sizeof(name)
    return value
