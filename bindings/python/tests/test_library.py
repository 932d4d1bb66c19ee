"""Loading: the library by SONAME or POLYMASS_LIBRARY, version and layout checks,
and the declarations that come from the header."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import polymass
from polymass import _header, _library
from polymass._library import ffi, lib


class _FakeLibrary:
    """Stands in for a different build of libpolymass: a version and struct sizes."""

    def __init__(self, version: int, size_change: int = 0) -> None:
        self.version = version
        self._text = ffi.new("char[]", f"{version // 10000}.{version // 100 % 100}.0".encode())
        for name in dir(lib):
            if name.startswith("polymass_sizeof_"):
                size = getattr(lib, name)() + size_change
                setattr(self, name, lambda size=size: size)

    def polymass_version(self) -> int:
        return self.version

    def polymass_version_string(self):
        return self._text


def _import_with(environment: dict) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", "import polymass"],
        env={**os.environ, **environment},
        capture_output=True,
        text=True,
        check=False,
    )


def test_the_loaded_library_is_the_version_built_against():
    assert polymass.library_version() == polymass.__version__
    assert lib.polymass_version() == _header.POLYMASS_VERSION_NUMBER


def test_every_struct_has_the_library_s_size():
    sizes = [name for name in dir(lib) if name.startswith("polymass_sizeof_")]
    assert sizes
    for function in sizes:
        struct = "polymass_" + function.removeprefix("polymass_sizeof_")
        assert getattr(lib, function)() == ffi.sizeof(struct)


@pytest.mark.parametrize("offset", [10000, -10000, -100])
def test_another_major_or_an_older_library_is_refused(offset):
    fake = _FakeLibrary(_header.POLYMASS_VERSION_NUMBER + offset)
    with pytest.raises(ImportError, match="the loaded C library is version"):
        _library._check_version(fake)


def test_a_newer_minor_library_is_accepted_with_longer_structs():
    fake = _FakeLibrary(_header.POLYMASS_VERSION_NUMBER + 100, size_change=8)
    _library._check_version(fake)
    _library._check_struct_sizes(fake)


@pytest.mark.parametrize(("minor", "size_change"), [(0, 8), (0, -8), (100, -8)])
def test_a_struct_layout_that_disagrees_is_refused(minor, size_change):
    fake = _FakeLibrary(_header.POLYMASS_VERSION_NUMBER + minor, size_change)
    with pytest.raises(ImportError, match="bytes in the loaded library"):
        _library._check_struct_sizes(fake)


def test_a_missing_library_is_an_import_error_naming_the_variable_and_soname():
    result = _import_with({"POLYMASS_LIBRARY": "/nonexistent/libpolymass.so.1"})
    assert result.returncode != 0
    assert "ImportError" in result.stderr
    assert "POLYMASS_LIBRARY=/nonexistent/libpolymass.so.1" in result.stderr
    assert "libpolymass.so.1" in result.stderr.split("POLYMASS_LIBRARY=")[-1]


def test_the_library_is_found_by_soname_on_the_loader_path():
    library = Path(os.environ.get("POLYMASS_LIBRARY", ""))
    if not library.is_file():
        pytest.skip("POLYMASS_LIBRARY is not set to a file: the SONAME path is the default")
    environment = {"LD_LIBRARY_PATH": str(library.parent), "POLYMASS_LIBRARY": ""}
    result = _import_with(environment)
    assert result.returncode == 0, result.stderr


def test_every_exported_function_is_declared():
    """The declarations come from the header: nothing the library exports is missing."""
    library = os.environ.get("POLYMASS_LIBRARY")
    nm = shutil.which("nm")
    if not (library and nm):
        pytest.skip("needs POLYMASS_LIBRARY and nm")
    symbols = subprocess.run(
        [nm, "-D", "--defined-only", library], capture_output=True, text=True, check=True
    ).stdout.split()
    exported = {s.split("@")[0] for s in symbols if s.startswith("polymass_")}
    assert exported and exported <= set(dir(lib))
