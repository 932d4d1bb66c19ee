#!/usr/bin/env bash
# Line coverage of src/ by the test suite: the `coverage` preset (Clang
# source-based coverage, Debug) built, its unit, core and cli tests run, and
# llvm-cov's report of every file under src/ written:
#
#   build/coverage/report.txt   lines, functions and regions per file
#   build/coverage/summary.txt  lines run and not run per part (core, capi, cli)
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
# Lines with code per part of src/ (core, capi, cli), as docs/coverage.md
# gives them: the source lines of the lcov export's DA records, each counted
# once and run if any record ran it. (Its LF and LH count a lambda's lines in
# the lambda and again in the function around it - 125 lines for the 67 of
# capi/polygon_api.cpp - and a header once per spelling of its path, which
# ccache rewrites to a relative one in some compiles.)
llvm-cov export -format=lcov -instr-profile "$OUT/coverage.profdata" "${objects[@]}" "${filter[@]}" |
    awk -F'[:,]' '/^SF:/ { file = $2; sub(/.*\/src\//, "", file); part = file; sub(/\/.*/, "", part) }
                  /^DA:/ { line = file ":" $2
                           if (!(line in found)) { found[line] = 1; lines[part]++ }
                           if ($3 > 0 && !(line in hit)) { hit[line] = 1; run[part]++ } }
                  END { for (part in lines)
                            printf "src/%s: %d lines, %d not run, %.1f %%\n", part, lines[part],
                                   lines[part] - run[part], 100 * run[part] / lines[part] }' |
    sort | tee "$OUT/summary.txt"
echo "coverage: $OUT/report.txt, $OUT/summary.txt, $OUT/html/index.html"
