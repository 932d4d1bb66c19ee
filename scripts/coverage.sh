#!/usr/bin/env bash
# Line coverage of src/ by the test suite: the `coverage` preset (Clang
# source-based coverage, Debug) built, its unit, core and cli tests run, and
# llvm-cov's report of every file under src/ written:
#
#   build/coverage/report.txt   lines, functions and regions per file
#   build/coverage/html/        each file annotated (index.html)
#
#   scripts/coverage.sh
#
# Not a step of scripts/test.sh (a full extra build; about 10 minutes on two
# cores). docs/coverage.md says what stays uncovered and why.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
OUT=$ROOT/build/coverage
PROFILES=$OUT/profiles

cmake --preset coverage
cmake --build --preset coverage
rm -rf "$PROFILES"
# Every process writes its own profile (LLVM_PROFILE_FILE of the preset);
# the tests of the package and ABI gate build or inspect other copies.
ctest --preset coverage --label-regex '^(unit|core|cli)$' || echo "coverage: some tests failed (the report covers what ran)"

llvm-profdata merge -sparse "$PROFILES"/*.profraw -o "$OUT/coverage.profdata"
objects=("$OUT/src/libpolymass.so")
while IFS= read -r exe; do
    objects+=(-object "$exe")
done < <(find "$OUT/tests" "$OUT/src/cli" -maxdepth 2 -type f -executable -name 'test_*' -o \
    -maxdepth 2 -type f -executable -name 'polymass' | sort)
# Only src/: not the tests, the generated header, Eigen, CLI11 and the like.
# Paths are relative to the build directory (where ninja runs every compile)
# when ccache rewrote them (CCACHE_BASEDIR, which scripts/test.sh sets).
filter=(-compilation-dir="$OUT" -ignore-filename-regex '(/tests/|/include/|^/usr/)')
llvm-cov report -instr-profile "$OUT/coverage.profdata" "${objects[@]}" "${filter[@]}" \
    | tee "$OUT/report.txt"
llvm-cov show -format=html -output-dir "$OUT/html" -instr-profile "$OUT/coverage.profdata" \
    "${objects[@]}" "${filter[@]}" >/dev/null
echo "coverage: $OUT/report.txt, $OUT/html/index.html"
