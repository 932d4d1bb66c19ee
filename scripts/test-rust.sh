#!/usr/bin/env bash
# Tests the Rust binding (bindings/rust: polymass-sys, polymass) and runs the
# Rust examples (examples/rust), then prints a summary with the test count.
#
#   scripts/test-rust.sh
#
# The C library comes from POLYMASS_LIB_DIR if set (e.g. build/rs/src, with
# POLYMASS_INCLUDE_DIR if its headers are not beside it), otherwise from the
# `release` preset's build tree, which is configured if missing and brought up
# to date (library targets only). POLYMASS_LIB_DIR is always passed to cargo,
# so an installed polymass.pc never replaces the library under test.
#
# The shared library is found at run time through LD_LIBRARY_PATH, set here:
# polymass-sys cannot give the binaries of the crates using it an rpath
# (cargo's rustc-link-arg reaches only the crate's own targets), and a path
# into a build tree does not belong in a binary. The last step links the
# library statically (feature `static`) and runs an example without it.
#
# Steps: fmt (cargo fmt --check), clippy (-D warnings), test (the workspace's
# unit, integration and doc tests), bindgen (a fresh bindgen run over the
# header matches the committed polymass-sys/src/bindings.rs), doc (rustdoc,
# -D warnings), examples (both, on the bundled bracket STL), static (an example
# linked with libpolymass.a), bundled (bundled-check, a crate outside the
# workspace depending on polymass with the feature `bundled`, built in a fresh
# target directory with no POLYMASS_* variable and run). Exits non-zero if any
# step fails; the later steps still run. Non-interactive.
set -uo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORKSPACE=$ROOT/bindings/rust
# Cargo's build artefacts live outside the checkout, shared by the clones on
# this machine (set CARGO_TARGET_DIR to choose): a fresh clone compiles its own
# crates, not bindgen and the other dependencies again. Cargo keys a crate by
# its path and fingerprints its sources (and polymass-sys the library it
# links), so clones never use each other's builds.
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/polymass/cargo-target}
LOG_DIR=$ROOT/build/test-logs
mkdir -p "$LOG_DIR"
TEST_LOG=$LOG_DIR/rust-test.log

# The workspace's rust-version (Cargo.toml); cargo enforces it, this only
# makes the message about a too-old toolchain come first and say what to do.
# (bindgen's libclang comes from Debian's libclang-dev: scripts/install-deps.sh.)
MSRV=$(sed -nE 's/^rust-version = "([0-9.]+)"/\1/p' "$WORKSPACE/Cargo.toml")

need_toolchain() {
    if ! command -v cargo >/dev/null 2>&1; then
        cat >&2 <<EOF
test-rust.sh: cargo not found. The binding needs Rust $MSRV or newer, newer than
Debian bookworm's cargo package (1.65): install it with rustup,
  curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal \\
      --component rustfmt,clippy
then open a new shell (or: . "\$HOME/.cargo/env") and run this again.
EOF
        return 1
    fi
    local version
    version=$(rustc --version | sed -E 's/^rustc ([0-9]+\.[0-9]+).*/\1/')
    if [ "$(printf '%s\n%s\n' "$MSRV" "$version" | sort -V | head -n 1)" != "$MSRV" ]; then
        echo "test-rust.sh: rustc $version is older than the binding's rust-version $MSRV:" \
            "rustup update stable" >&2
        return 1
    fi
    local component
    for component in rustfmt clippy; do
        if ! cargo "${component/rustfmt/fmt}" --version >/dev/null 2>&1; then
            echo "test-rust.sh: cargo ${component/rustfmt/fmt} is missing:" \
                "rustup component add $component" >&2
            return 1
        fi
    done
}

# Sets POLYMASS_LIB_DIR, building the release preset's library if needed.
find_library() {
    if [ -n "${POLYMASS_LIB_DIR:-}" ]; then
        echo "library: POLYMASS_LIB_DIR=$POLYMASS_LIB_DIR"
        return 0
    fi
    (
        cd "$ROOT" || exit 1
        if [ ! -f build/release/CMakeCache.txt ]; then
            cmake --preset release || exit 1
        fi
        cmake --build --preset release --target polymass polymass_static
    ) || return 1
    export POLYMASS_LIB_DIR=$ROOT/build/release/src
    echo "library: $POLYMASS_LIB_DIR (release preset)"
}

step_fmt() {
    cargo fmt --all --check
}

step_clippy() {
    cargo clippy --locked --workspace --all-targets -- -D warnings
}

step_test() {
    cargo test --locked --workspace 2>&1 | tee "$TEST_LOG"
}

step_bindgen() {
    cargo test --locked -p polymass-sys --features buildtime-bindgen \
        --test bindings_up_to_date 2>&1 | tee -a "$TEST_LOG"
}

step_doc() {
    # Broken intra-doc links and undocumented public items fail.
    RUSTDOCFLAGS="-D warnings" cargo doc --locked --no-deps --workspace
}

step_examples() {
    cargo run --locked -q -p polymass-examples --bin mass_properties || return 1
    # The bundled robot link is in millimetres: aluminium is 2.7e-6 kg/mm^3.
    cargo run --locked -q -p polymass-examples --bin stl_mass_properties -- \
        "$ROOT/examples/data/robot_link.stl" 2.7e-6
}

step_static() {
    # Built into its own target directory, so the dynamically linked builds
    # of the other steps are not rebuilt next time.
    CARGO_TARGET_DIR=$CARGO_TARGET_DIR-static env -u LD_LIBRARY_PATH \
        cargo run --locked -q -p polymass-examples --features polymass/static \
        --bin mass_properties
}

step_bundled() {
    local target=$ROOT/build/rust-bundled-check
    rm -rf "$target"
    env -u POLYMASS_LIB_DIR -u POLYMASS_INCLUDE_DIR -u LD_LIBRARY_PATH CARGO_TARGET_DIR="$target" \
        cargo run --locked --manifest-path "$WORKSPACE/bundled-check/Cargo.toml"
}

# --------------------------------------------------------------------------

need_toolchain || exit 1
find_library || {
    echo "test-rust.sh: building the C library failed" >&2
    exit 1
}
export LD_LIBRARY_PATH=$POLYMASS_LIB_DIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
cd "$WORKSPACE" || exit 1

STEPS=(fmt clippy test bindgen doc examples static bundled)
declare -A RESULT
failed=0
for step in "${STEPS[@]}"; do
    echo
    echo "==================== rust: $step ===================="
    if "step_$step"; then
        RESULT[$step]=PASS
    else
        RESULT[$step]=FAIL
        failed=$((failed + 1))
    fi
done

# Every "test result:" line of cargo test: unit, integration and doc tests.
passed_tests=0
failed_tests=0
if [ -f "$TEST_LOG" ]; then
    while read -r passed failed_count; do
        passed_tests=$((passed_tests + passed))
        failed_tests=$((failed_tests + failed_count))
    done < <(sed -nE 's/^test result: [A-Za-z]+\. ([0-9]+) passed; ([0-9]+) failed.*/\1 \2/p' "$TEST_LOG")
fi

echo
echo "==================== rust: summary ===================="
for step in "${STEPS[@]}"; do
    printf '  %-9s %s\n' "$step" "${RESULT[$step]}"
done
echo "rust tests: $passed_tests passed, $failed_tests failed (cargo test log: $TEST_LOG)"
if [ $failed -ne 0 ]; then
    echo "test-rust.sh: $failed step(s) failed"
    exit 1
fi
echo "test-rust.sh: all steps passed"
