"""Build step: generate the cffi module from the installed or in-tree polymass.h.

The declarations and constants come from the real header (cdef_from_header.py),
so the binding cannot drift from the library. The header is looked for in:

1. POLYMASS_INCLUDE_DIR: directories separated by os.pathsep, holding
   polymass/polymass.h and polymass/polymass_version.h (an installed prefix's
   include/, or a source include/ plus a build tree's include/);
2. the repository this package sits in (bindings/python -> ../../include), with
   polymass_version.h made from its template and the version in CMakeLists.txt;
3. pkg-config's include directory for polymass.

The generated module is cffi's out-of-line ABI mode: no compiler is needed, and
the shared library is opened at import (see polymass/_library.py).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cdef_from_header import read_header  # noqa: E402

REPOSITORY = HERE.parent.parent
VERSION_HEADER = "polymass/polymass_version.h"


def _repository_include_dirs(scratch: Path) -> list[Path] | None:
    """The source tree's include/ and a version header configured like CMake does."""
    include = REPOSITORY / "include"
    template = include / (VERSION_HEADER + ".in")
    cmake_lists = REPOSITORY / "CMakeLists.txt"
    if not (include / "polymass/polymass.h").is_file() or not template.is_file():
        return None
    match = re.search(
        r"project\(\s*polymass\s+VERSION\s+(\d+)\.(\d+)\.(\d+)", cmake_lists.read_text()
    )
    if not match:
        raise RuntimeError(f"no project(polymass VERSION x.y.z) in {cmake_lists}")
    major, minor, patch = match.groups()
    values = {
        "PROJECT_VERSION_MAJOR": major,
        "PROJECT_VERSION_MINOR": minor,
        "PROJECT_VERSION_PATCH": patch,
        "PROJECT_VERSION": f"{major}.{minor}.{patch}",
    }
    text = re.sub(r"@(\w+)@", lambda m: values[m.group(1)], template.read_text())
    (scratch / "polymass").mkdir(parents=True, exist_ok=True)
    (scratch / VERSION_HEADER).write_text(text)
    return [include, scratch]


def _pkg_config_include_dirs() -> list[Path] | None:
    try:
        result = subprocess.run(
            ["pkg-config", "--variable=includedir", "polymass"],
            capture_output=True,
            text=True,
            check=True,
        )
    except (OSError, subprocess.CalledProcessError):
        return None
    return [Path(result.stdout.strip())]


def _include_dirs(scratch: Path) -> list[Path]:
    from_environment = os.environ.get("POLYMASS_INCLUDE_DIR")
    if from_environment:
        return [Path(d) for d in from_environment.split(os.pathsep) if d]
    found = _repository_include_dirs(scratch) or _pkg_config_include_dirs()
    if not found:
        raise RuntimeError(
            "polymass.h not found: set POLYMASS_INCLUDE_DIR to the directory holding "
            "polymass/polymass.h and polymass/polymass_version.h, build from the libpolymass "
            "repository, or install libpolymass where pkg-config finds it"
        )
    return found


def _read_polymass_header():
    with tempfile.TemporaryDirectory() as scratch:
        directories = _include_dirs(Path(scratch))
        for directory in directories:
            if (directory / "polymass/polymass.h").is_file():
                return read_header(directory / "polymass/polymass.h", directories)
        searched = ", ".join(str(d) for d in directories)
        raise RuntimeError(f"polymass/polymass.h not found in {searched} (POLYMASS_INCLUDE_DIR)")


HEADER = _read_polymass_header()


class BuildWithGeneratedModules(build_py):
    """Writes polymass/_polymass_cffi.py and polymass/_header.py beside the sources."""

    def run(self):
        super().run()
        import cffi

        target = Path(self.build_lib) / "polymass"
        target.mkdir(parents=True, exist_ok=True)
        builder = cffi.FFI()
        builder.cdef(HEADER.cdef())
        builder.set_source("polymass._polymass_cffi", None)
        builder.emit_python_code(str(target / "_polymass_cffi.py"))
        lines = [
            '"""Constants of polymass.h, generated at build time by setup.py."""',
            "",
            *(f"{name} = {value!r}" for name, value in sorted(HEADER.constants.items())),
        ]
        (target / "_header.py").write_text("\n".join(lines) + "\n")


setup(
    version=HEADER.constants["POLYMASS_VERSION_STRING"],
    cmdclass={"build_py": BuildWithGeneratedModules},
)
