"""The PEP 517 build backend of the polymass package: scikit-build-core, given the C sources.

The wheel carries libpolymass, built by CMake (CMakeLists.txt beside pyproject.toml) from
the library's own sources in ``libpolymass/``, where pyproject.toml also reads the version
(``project(polymass VERSION x.y.z)``). In an sdist that directory is part of the archive;
in the libpolymass repository (this package is its ``bindings/python``) every hook first
copies what the library's build needs into it from the repository, and removes the copy
afterwards: so the sdist carries the sources, and nothing of them is kept twice in git.
"""

from __future__ import annotations

import shutil
from contextlib import contextmanager
from pathlib import Path

from scikit_build_core import build as _scikit_build

PROJECT = Path(__file__).resolve().parent.parent
SOURCES = PROJECT / "libpolymass"
REPOSITORY = PROJECT.parent.parent
# What building the library needs, relative to the repository root: not the tool
# (src/cli), the tests or the examples, which CMakeLists.txt turns off.
LIBRARY_FILES = (
    "CMakeLists.txt",
    "LICENSE",
    "cmake",
    "include",
    "src/CMakeLists.txt",
    "src/capi",
    "src/core",
)


def _in_repository() -> bool:
    return (REPOSITORY / "bindings/python").resolve() == PROJECT and (
        REPOSITORY / "include/polymass/polymass.h"
    ).is_file()


@contextmanager
def _library_sources():
    """libpolymass/ holds the library's sources while the hook runs."""
    if not _in_repository():
        if not (SOURCES / "include/polymass/polymass.h").is_file():
            raise RuntimeError(
                f"the libpolymass sources are missing: {SOURCES} is empty and {PROJECT} is not "
                "the bindings/python directory of a libpolymass repository"
            )
        yield
        return
    shutil.rmtree(SOURCES, ignore_errors=True)
    try:
        for name in LIBRARY_FILES:
            source, target = REPOSITORY / name, SOURCES / name
            target.parent.mkdir(parents=True, exist_ok=True)
            if source.is_dir():
                shutil.copytree(source, target)
            else:
                shutil.copy2(source, target)
        yield
    finally:
        shutil.rmtree(SOURCES, ignore_errors=True)


def get_requires_for_build_sdist(config_settings=None):
    with _library_sources():
        return _scikit_build.get_requires_for_build_sdist(config_settings)


def get_requires_for_build_wheel(config_settings=None):
    with _library_sources():
        return _scikit_build.get_requires_for_build_wheel(config_settings)


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    with _library_sources():
        return _scikit_build.prepare_metadata_for_build_wheel(metadata_directory, config_settings)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    with _library_sources():
        return _scikit_build.build_wheel(wheel_directory, config_settings, metadata_directory)


def build_sdist(sdist_directory, config_settings=None):
    with _library_sources():
        return _scikit_build.build_sdist(sdist_directory, config_settings)
