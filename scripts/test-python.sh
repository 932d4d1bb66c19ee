#!/usr/bin/env bash
# Tests the Python binding (bindings/python) the way a user installs it:
#   1. builds the library (target polymass) with the release preset, incrementally,
#      unless POLYMASS_LIBRARY already names a libpolymass.so.1 to test;
#   2. creates build/python-venv once;
#   3. pip-installs bindings/python into it, not editable, to prove it installs, with
#      its [test] extra and ruff (pip rebuilds a local directory every time, and
#      leaves the dependencies alone when they are satisfied);
#   4. ruff format --check and ruff check over every Python file of the repository
#      (ruff.toml; .gitignore'd build trees are skipped);
#   5. pytest (bindings/python/tests), then runs the examples;
#   6. the Dask example (examples/dask): dask[distributed] and pyarrow from PyPI,
#      then its pytest on a distributed.LocalCluster.
#
#   scripts/test-python.sh            PYTHON=python3.12 scripts/test-python.sh
#
# Non-interactive; assumes scripts/install-deps.sh ran (python3-venv). Exits
# non-zero at the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
venv=$root/build/python-venv
python=${PYTHON:-python3}

step() { printf '\n==================== python: %s ====================\n' "$1"; }

step library
if [ -z "${POLYMASS_LIBRARY:-}" ]; then
    [ -f build/release/CMakeCache.txt ] || cmake --preset release </dev/null
    cmake --build --preset release --target polymass </dev/null  # the library alone
    export POLYMASS_LIBRARY=$root/build/release/src/libpolymass.so.1
fi
[ -f "$POLYMASS_LIBRARY" ] || { echo "test-python: no library at $POLYMASS_LIBRARY" >&2; exit 1; }
echo "POLYMASS_LIBRARY=$POLYMASS_LIBRARY"

step install
[ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
"$venv/bin/python" -m pip --disable-pip-version-check --no-input --quiet \
    install "./bindings/python[test]" ruff </dev/null
"$venv/bin/python" -c 'import polymass; print("polymass", polymass.__version__, "C library", polymass.library_version())'

step ruff
"$venv/bin/ruff" format --check .
"$venv/bin/ruff" check .

step pytest
# From bindings/python: its pyproject.toml holds the pytest settings. The package
# under test is the installed one (src/ layout: nothing shadows it).
(cd bindings/python && "$venv/bin/python" -m pytest -q -p no:cacheprovider </dev/null)

step examples
"$venv/bin/python" examples/python/mass_properties_of_file.py </dev/null
"$venv/bin/python" examples/python/batch_threads.py </dev/null | tail -n 3

step dask
"$venv/bin/python" -m pip --disable-pip-version-check --no-input --quiet \
    install "dask[distributed]" pyarrow </dev/null
"$venv/bin/python" -m pytest -q -p no:cacheprovider examples/dask </dev/null

echo
echo "test-python: all passed"
