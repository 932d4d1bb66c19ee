"""Loading: the package's own copy of the library or the one POLYMASS_LIBRARY names,
version and layout checks, and the declarations that come from the header."""

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


def test_a_library_without_a_function_of_the_header_is_refused():
    fake = _FakeLibrary(_header.POLYMASS_VERSION_NUMBER)

    def missing():
        raise AttributeError("undefined symbol: polymass_sizeof_shell")

    fake.polymass_sizeof_shell = missing
    with pytest.raises(ImportError, match="has no polymass_sizeof_shell"):
        _library._check_struct_sizes(fake)


def test_a_missing_library_is_an_import_error_naming_the_variable_and_soname():
    result = _import_with({"POLYMASS_LIBRARY": "/nonexistent/libpolymass.so.2"})
    assert result.returncode != 0
    assert "ImportError" in result.stderr
    assert "POLYMASS_LIBRARY=/nonexistent/libpolymass.so.2" in result.stderr
    assert "libpolymass.so.2" in result.stderr.split("POLYMASS_LIBRARY=")[-1]


_LOADED_LIBRARY = (
    "import polymass, pathlib; "
    "print(next(line.split()[-1] for line in pathlib.Path('/proc/self/maps').read_text()"
    ".splitlines() if 'libpolymass' in line))"
)


def _loaded_library(environment: dict) -> Path:
    """The file of libpolymass mapped by a fresh interpreter that imports polymass."""
    if not Path("/proc/self/maps").is_file():
        pytest.skip("needs /proc/self/maps")
    result = subprocess.run(
        [sys.executable, "-c", _LOADED_LIBRARY],
        env={**os.environ, **environment},
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    return Path(result.stdout.strip())


def test_without_the_variable_the_package_s_own_copy_is_loaded():
    loaded = _loaded_library({"POLYMASS_LIBRARY": ""})
    assert loaded == Path(polymass.__file__).resolve().with_name("libpolymass.so.2")


def test_the_variable_may_name_the_library_the_loader_finds(tmp_path):
    """POLYMASS_LIBRARY=libpolymass.so.2 asks for the system's library (here: one on
    LD_LIBRARY_PATH) rather than the package's copy."""
    system = tmp_path / "libpolymass.so.2"
    shutil.copyfile(_loaded_library({"POLYMASS_LIBRARY": ""}), system)
    loaded = _loaded_library(
        {"POLYMASS_LIBRARY": "libpolymass.so.2", "LD_LIBRARY_PATH": str(tmp_path)}
    )
    assert loaded == system


def test_every_exported_function_is_declared():
    """The declarations come from the header: nothing the library exports is missing."""
    nm = shutil.which("nm")
    if not nm:
        pytest.skip("needs nm")
    library = _loaded_library({})
    symbols = subprocess.run(
        [nm, "-D", "--defined-only", str(library)], capture_output=True, text=True, check=True
    ).stdout.split()
    exported = {s.split("@")[0] for s in symbols if s.startswith("polymass_")}
    assert exported and exported <= set(dir(lib))
