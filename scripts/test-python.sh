#!/usr/bin/env bash
# Tests the Python binding (bindings/python) the way a user gets it:
#   1. builds an sdist (python -m build --sdist: the package plus the library's
#      C++ sources), then a wheel from that sdist, outside the repository (pip
#      wheel: scikit-build-core builds libpolymass into it), in build/python-dist;
#   2. installs the wheel into a second, fresh venv (build/python-venv-fresh, made
#      anew each time) and computes a tetrahedron's volume there, exactly;
#   3. installs the same wheel, with its [test] extra and ruff, into
#      build/python-venv (made once; pip leaves satisfied dependencies alone);
#   4. ruff format --check and ruff check over every Python file of the repository
#      (ruff.toml; .gitignore'd build trees are skipped);
#   5. pytest (bindings/python/tests); its threading tests again on the library
#      built with ThreadSanitizer (build/tsan, when the tsan step made it);
#      then runs the examples;
#   6. the Dask example (examples/dask): dask[distributed] and pyarrow from PyPI,
#      then its pytest on a distributed.LocalCluster;
#   7. polymass audit --fix read back by yourdfpy and MuJoCo (from PyPI):
#      tests/cli/test_audit_consumers.py; and the audit's MJCF inertials
#      against MuJoCo's own compile of models exercising each mass rule:
#      tests/cli/test_audit_mujoco.py; both with the tool of build/dev (or
#      $POLYMASS_EXE; scripts/test.sh builds dev before this step);
#   8. polymass --usda read back by OpenUSD (usd-core from PyPI):
#      tests/cli/test_usd.py, with the same tool.
# The library under test is the wheel's own copy: POLYMASS_LIBRARY is unset.
#
#   scripts/test-python.sh            PYTHON=python3.12 scripts/test-python.sh
#
# Non-interactive; assumes scripts/install-deps.sh ran (python3-venv, a C++
# compiler, CMake, Eigen). Exits non-zero at the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
venv=$root/build/python-venv
fresh_venv=$root/build/python-venv-fresh
dist=$root/build/python-dist
python=${PYTHON:-python3}
pip_options=(--disable-pip-version-check --no-input --quiet)
unset POLYMASS_LIBRARY

step() { printf '\n==================== python: %s ====================\n' "$1"; }

step sdist
[ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
"$venv/bin/python" -m pip "${pip_options[@]}" install build ruff </dev/null
rm -rf "$dist"
"$venv/bin/python" -m build --sdist --outdir "$dist" bindings/python </dev/null
sdist=$(ls "$dist"/polymass-*.tar.gz)
case $(tar -tzf "$sdist") in
*/libpolymass/src/core/*.cpp*) ;;
*) echo "test-python: the sdist carries no C++ sources" >&2; exit 1 ;;
esac
echo "$sdist"

step wheel
# Built from the sdist's files alone, unpacked at a fixed place and built in a
# fixed directory (pip's own would be random temporary ones), so that the test
# command's compiler cache recognises the compiles of a previous run.
unpacked=$root/build/python-sdist
rm -rf "$unpacked" "$root/build/python-wheel-build"
mkdir -p "$unpacked"
tar -xzf "$sdist" -C "$unpacked" --strip-components=1
"$venv/bin/python" -m pip "${pip_options[@]}" wheel --no-deps --wheel-dir "$dist" \
    --config-settings=build-dir="$root/build/python-wheel-build" "$unpacked" </dev/null
wheel=$(ls "$dist"/polymass-*.whl)
echo "$wheel"

step fresh-venv
rm -rf "$fresh_venv"
"$python" -m venv "$fresh_venv"
"$fresh_venv/bin/python" -m pip "${pip_options[@]}" install "$wheel" </dev/null
# From / so that nothing of the repository is importable; 6 is exact in binary.
(cd / && "$fresh_venv/bin/python" - <<'PYTHON'
import numpy as np
import polymass

vertices = np.array([[0, 0, 0], [6, 0, 0], [0, 6, 0], [0, 0, 1]], dtype=float)
faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
volume = polymass.mass_properties(vertices, faces).volume
assert volume == 6.0, f"tetrahedron volume {volume!r}, expected exactly 6"
print(f"fresh venv: polymass {polymass.__version__}, tetrahedron volume {volume!r}")
PYTHON
)

step install
"$venv/bin/python" -m pip "${pip_options[@]}" install --force-reinstall --no-deps "$wheel" </dev/null
"$venv/bin/python" -m pip "${pip_options[@]}" install "$wheel[test]" </dev/null
"$venv/bin/python" -c 'import polymass, polymass._library as l; print("polymass", polymass.__version__, "C library", polymass.library_version(), "from", l.source)'

step ruff
"$venv/bin/ruff" format --check .
"$venv/bin/ruff" check .

step pytest
# From bindings/python: its pyproject.toml holds the pytest settings. The package
# under test is the installed one (src/ layout: nothing shadows it).
(cd bindings/python && "$venv/bin/python" -m pytest -q -p no:cacheprovider </dev/null)

step threads-under-tsan
# The binding's threading tests again, on the library built with
# ThreadSanitizer (the tsan step's build/tsan, which runs before this one in
# scripts/test.sh): Python threads, each calling the library, which runs its
# own workers. The interpreter is not instrumented; libtsan is preloaded so
# that it sees every thread and lock.
tsan_library=$root/build/tsan/src/libpolymass.so.2
if [ -f "$tsan_library" ]; then
    (cd bindings/python && POLYMASS_LIBRARY=$tsan_library \
        LD_PRELOAD=$(gcc -print-file-name=libtsan.so) TSAN_OPTIONS=halt_on_error=1 \
        "$venv/bin/python" -m pytest -q -p no:cacheprovider tests/test_threads.py \
        tests/test_batch.py </dev/null)
else
    echo "skipped: no ThreadSanitizer build at $tsan_library (scripts/test.sh tsan makes it)"
fi

step examples
"$venv/bin/python" examples/python/mass_properties_of_file.py </dev/null
"$venv/bin/python" examples/python/batch_threads.py </dev/null | tail -n 3

step dask
"$venv/bin/python" -m pip --disable-pip-version-check --no-input --quiet \
    install "dask[distributed]" pyarrow </dev/null
"$venv/bin/python" -m pytest -q -p no:cacheprovider examples/dask </dev/null

step audit-consumers
polymass_exe=${POLYMASS_EXE:-$root/build/dev/src/cli/polymass}
if [ ! -x "$polymass_exe" ]; then
    echo "test-python: no polymass tool at $polymass_exe (build the dev preset first)" >&2
    exit 1
fi
# MuJoCo pinned to the major version the MJCF rules were read from (its
# compiler's defaults, such as legacy mesh inertia, change between them).
"$venv/bin/python" -m pip "${pip_options[@]}" install yourdfpy 'mujoco==4.0.*' </dev/null
POLYMASS_EXE=$polymass_exe "$venv/bin/python" -m pytest -q -p no:cacheprovider \
    tests/cli/test_audit_consumers.py tests/cli/test_audit_mujoco.py </dev/null

step usd
"$venv/bin/python" -m pip "${pip_options[@]}" install 'usd-core==26.*' </dev/null
POLYMASS_EXE=$polymass_exe "$venv/bin/python" -m pytest -q -p no:cacheprovider \
    tests/cli/test_usd.py </dev/null

echo
echo "test-python: all passed"
