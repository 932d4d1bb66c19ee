#!/usr/bin/env bash
# Runs every test of libpolymass, step by step, and prints a summary.
#
#   scripts/test.sh            all steps
#   scripts/test.sh dev asan   only the named steps
#
# Steps (each one a function step_<name> below; add new ones to STEPS):
#   deps    scripts/install-deps.sh (apt-get only for what is missing)
#   format  clang-format --dry-run --Werror over the C/C++ sources
#   dev     configure, build and ctest the `dev` preset (Debug, -Werror)
#   asan    configure, build and ctest the `asan` preset (ASan + UBSan)
#   fuzz    configure, build and ctest the `fuzz` preset (Clang, libFuzzer):
#           each target of tests/fuzz (the C API, the tool's readers, audit and
#           command line, the moments): its regressions replayed, then a
#           bounded, fixed-seed run
#   tsan    configure, build and ctest the `tsan` preset (ThreadSanitizer):
#           the library and its threading unit tests only (threads, batch,
#           packed, concurrent_calls, welding, intersections: contexts on many
#           threads, one mesh read by many, the library's workers, batches,
#           the intersection check's search ended on two threads)
#   python  scripts/test-python.sh: the Python binding installed into a venv,
#           ruff over every Python file, pytest, the Python examples
#   rust    scripts/test-rust.sh: rustfmt, clippy, cargo test (with doc
#           tests), rustdoc, the Rust examples; against the dev step's
#           library when build/dev is there
#   debian  scripts/test-debian.sh: the Debian packages (debian/) built from a
#           copy of the tree with dpkg-buildpackage, lintian (no error, no
#           warning), the packaged tool run once
#
# Exits non-zero if any step fails; the later steps still run, so one run
# shows every failure. Idempotent: build trees under build/ are reused.
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
LOG_DIR=$ROOT/build/test-logs
mkdir -p "$LOG_DIR"
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-2}
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-2}

STEPS=(deps format dev asan tsan fuzz python rust debian)

# Every C/C++ compile of every step - the presets, the CMake builds inside the
# Python wheel and the Rust crates, the Debian package - goes through ccache
# once it is installed (the deps step installs it), so a run after a small
# change recompiles only what changed. Paths under the root are hashed as
# relative ones, so a fresh clone in another directory hits the same cache.
# POLYMASS_NO_CCACHE=1 compiles everything afresh.
use_ccache() {
    if [ -z "${POLYMASS_NO_CCACHE:-}" ] && command -v ccache >/dev/null 2>&1; then
        export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
        export CCACHE_BASEDIR=$ROOT CCACHE_NOHASHDIR=true
    fi
}

# Counts of test cases (ctest) across the steps, for the closing line.
TESTS_PASSED=0
TESTS_FAILED=0

# Adds ctest's "N% tests passed, F tests failed out of T" from a log.
count_ctest() { # <log>
    local line total failed
    line=$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -n 1)
    if [ -z "$line" ]; then
        return
    fi
    failed=$(sed -E 's/.* ([0-9]+) tests? failed out of.*/\1/' <<<"$line")
    total=$(sed -E 's/.*out of ([0-9]+).*/\1/' <<<"$line")
    TESTS_FAILED=$((TESTS_FAILED + failed))
    TESTS_PASSED=$((TESTS_PASSED + total - failed))
}

step_deps() {
    bash scripts/install-deps.sh
}

step_format() {
    local files=()
    # tests/abi/baseline holds a released header, frozen byte for byte: not
    # reformatted, whatever clang-format's version says.
    mapfile -t files < <(find include src tests examples -type f \
        \( -name '*.c' -o -name '*.h' -o -name '*.cpp' -o -name '*.hpp' -o -name '*.cc' -o -name '*.hh' \) \
        -not -path '*/build/*' -not -path 'tests/abi/baseline/*' 2>/dev/null | sort)
    if [ ${#files[@]} -eq 0 ]; then
        echo "no C/C++ files found"
        return 1
    fi
    echo "clang-format $(clang-format --version | sed -E 's/.*version ([0-9.]+).*/\1/') on ${#files[@]} files"
    local bad=() file
    for file in "${files[@]}"; do
        # Generated files (e.g. tests/unit/reference/exact_reference.h) are
        # what their generator writes, formatted or not.
        if head -n 5 "$file" | grep -qE 'DO NOT EDIT|@generated'; then
            echo "  skipped (generated): $file"
            continue
        fi
        if ! clang-format --dry-run --Werror "$file" >/dev/null 2>&1; then
            bad+=("$file")
        fi
    done
    if [ ${#bad[@]} -eq 0 ]; then
        echo "all formatted"
        return 0
    fi
    echo "${#bad[@]} file(s) not formatted (fix: clang-format -i <file>...):"
    printf '  %s\n' "${bad[@]}"
    # The changes clang-format wants, at most 150 lines of them.
    for file in "${bad[@]}"; do
        clang-format "$file" | diff -u --label "$file" --label "$file (clang-format)" "$file" - || true
    done | head -n 150
    return 1
}

# configure + build + ctest of one preset, logged to build/test-logs/<preset>.log
preset_workflow() { # <preset>
    local preset=$1 log=$LOG_DIR/$1.log rc=0
    : >"$log"
    cmake --preset "$preset" 2>&1 | tee -a "$log" || return 1
    cmake --build --preset "$preset" 2>&1 | tee -a "$log" || return 1
    ctest --preset "$preset" 2>&1 | tee -a "$log" || rc=1
    count_ctest "$log"
    return $rc
}

step_dev() {
    preset_workflow dev
}

step_asan() {
    preset_workflow asan
}

# The fuzz build's coverage ignore list is read by the compiler, unseen by
# ccache, which is told to hash it (for this step only: the others' objects
# would all change key).
step_fuzz() {
    CCACHE_EXTRAFILES=$ROOT/tests/fuzz/coverage-ignorelist.txt preset_workflow fuzz
}

step_tsan() {
    preset_workflow tsan
}

# Adds the "N passed" / "F failed" of every pytest closing line of a log (the
# binding's suite, then the Dask example's).
count_pytest() { # <log>
    local line
    while IFS= read -r line; do
        TESTS_PASSED=$((TESTS_PASSED + $(grep -oE '[0-9]+ passed' <<<"$line" | grep -oE '[0-9]+' || echo 0)))
        TESTS_FAILED=$((TESTS_FAILED + $(grep -oE '[0-9]+ failed' <<<"$line" | grep -oE '[0-9]+' || echo 0)))
    done < <(grep -E '^=*.*[0-9]+ (passed|failed).* in [0-9.]+s' "$1")
}

step_python() {
    local log=$LOG_DIR/python.log rc=0
    bash scripts/test-python.sh </dev/null 2>&1 | tee "$log" || rc=1
    count_pytest "$log"
    return $rc
}

# Adds test-rust.sh's "rust tests: N passed, F failed" from a log.
count_rust() { # <log>
    local line
    line=$(grep -E '^rust tests: [0-9]+ passed, [0-9]+ failed' "$1" | tail -n 1)
    if [ -z "$line" ]; then
        return
    fi
    TESTS_PASSED=$((TESTS_PASSED + $(sed -E 's/^rust tests: ([0-9]+) passed.*/\1/' <<<"$line")))
    TESTS_FAILED=$((TESTS_FAILED + $(sed -E 's/.* ([0-9]+) failed.*/\1/' <<<"$line")))
}

step_rust() {
    local log=$LOG_DIR/rust.log rc=0
    # The crates are tested against the dev step's library when it is there
    # (brought up to date: a no-op after that step) rather than compiling the
    # library once more in the release preset; the bundled check still
    # compiles its own, as a user's cargo build does.
    local library=${POLYMASS_LIB_DIR:-}
    if [ -z "$library" ] && [ -f build/dev/CMakeCache.txt ]; then
        cmake --build build/dev --target polymass polymass_static </dev/null >"$LOG_DIR/rust-library.log" 2>&1 ||
            { cat "$LOG_DIR/rust-library.log"; return 1; }
        library=$ROOT/build/dev/src
    fi
    # (Empty: test-rust.sh builds the release preset's.)
    POLYMASS_LIB_DIR=$library bash scripts/test-rust.sh </dev/null 2>&1 | tee "$log" || rc=1
    count_rust "$log"
    return $rc
}

step_debian() {
    bash scripts/test-debian.sh </dev/null 2>&1 | tee "$LOG_DIR/debian.log"
}

# --------------------------------------------------------------------------

selected=("$@")
if [ ${#selected[@]} -eq 0 ]; then
    selected=("${STEPS[@]}")
fi
for step in "${selected[@]}"; do
    if ! declare -F "step_$step" >/dev/null; then
        echo "test.sh: unknown step '$step' (steps: ${STEPS[*]})" >&2
        exit 2
    fi
done

declare -A RESULT SECONDS_TAKEN
failed_steps=0
for step in "${selected[@]}"; do
    echo
    echo "==================== step: $step ===================="
    start=$SECONDS
    use_ccache
    if "step_$step"; then
        RESULT[$step]=PASS
        [ "$step" = format ] && TESTS_PASSED=$((TESTS_PASSED + 1))
    else
        RESULT[$step]=FAIL
        [ "$step" = format ] && TESTS_FAILED=$((TESTS_FAILED + 1))
        failed_steps=$((failed_steps + 1))
        if [ "$step" = deps ]; then
            echo "test.sh: installing the dependencies failed; stopping" >&2
            SECONDS_TAKEN[$step]=$((SECONDS - start))
            break
        fi
    fi
    SECONDS_TAKEN[$step]=$((SECONDS - start))
done

echo
echo "==================== summary ===================="
for step in "${selected[@]}"; do
    printf '  %-8s %-5s %4ss\n' "$step" "${RESULT[$step]:-SKIP}" "${SECONDS_TAKEN[$step]:-0}"
done
echo "  logs: $LOG_DIR"
# The closing line counts every ctest test of every preset, every pytest and
# cargo test case, plus the format check as one.
if [ $failed_steps -ne 0 ]; then
    echo "test.sh: $failed_steps step(s) failed"
    echo "tests: $TESTS_PASSED passed, $TESTS_FAILED failed"
    exit 1
fi
echo "test.sh: all steps passed"
echo "tests: $TESTS_PASSED passed, $TESTS_FAILED failed"
