#!/usr/bin/env bash
# A fuzzing campaign: every libFuzzer target of build/fuzz (or those named) in
# turn, each for SECONDS, one process at a time, and a line of figures per
# target. Unlike the bounded ctest runs (fuzz.*), a campaign goes on from
# where the last one stopped: each target's corpus is kept under
# ~/.cache/polymass/fuzz/<target>/corpus (seeded from the committed seeds and
# regressions), and it keeps going past findings (libFuzzer's fork mode with
# -ignore_crashes, -ignore_ooms, -ignore_timeouts), which it leaves as
# ~/.cache/polymass/fuzz/<target>/findings/{crash,leak,oom,timeout}-* to be
# shrunk, fixed and kept under the target's regressions/.
#
#   tests/fuzz/campaign.sh [SECONDS] [TARGET...]     (default: 600, every target)
#
# Prints, and appends to ~/.cache/polymass/fuzz/campaign.log, one line per
# target: its executions, libFuzzer's coverage (cov: edges reached, ft:
# features), the corpus size and the findings left. Build first:
#   cmake --preset fuzz && cmake --build --preset fuzz
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${POLYMASS_FUZZ_BUILD:-$ROOT/build/fuzz}/tests/fuzz
STORE=${XDG_CACHE_HOME:-$HOME/.cache}/polymass/fuzz
SECONDS_PER_TARGET=${1:-600}
shift || true
TARGETS=("$@")
if [ ${#TARGETS[@]} -eq 0 ]; then
    TARGETS=(mesh moments obj stl ply off msh gltf glb 3mf 3mf_model dae audit arguments)
fi

# The committed inputs of a target: seeds, regressions, dictionary.
sources_of() { # <target> -> sets seeds regressions dict
    if [ "$1" = mesh ]; then
        seeds=$ROOT/tests/fuzz/corpus regressions=$ROOT/tests/fuzz/regressions dict=
    else
        seeds=$ROOT/tests/fuzz/$1/corpus regressions=$ROOT/tests/fuzz/$1/regressions
        dict=$ROOT/tests/fuzz/$1/$1.dict
    fi
}

mkdir -p "$STORE"
for target in "${TARGETS[@]}"; do
    fuzzer=$BUILD/fuzz_$target
    if [ ! -x "$fuzzer" ]; then
        echo "campaign: no $fuzzer (build the fuzz preset)" >&2
        exit 2
    fi
    sources_of "$target"
    corpus=$STORE/$target/corpus findings=$STORE/$target/findings
    mkdir -p "$corpus" "$findings"
    for dir in "$seeds" "$regressions"; do
        [ -d "$dir" ] && find "$dir" -maxdepth 1 -type f ! -name 'README*' -exec cp -n {} "$corpus/" \;
    done
    options=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1
        -max_total_time="$SECONDS_PER_TARGET" -rss_limit_mb=2048 -timeout=30
        -artifact_prefix="$findings/")
    [ -n "$dict" ] && [ -f "$dict" ] && options+=(-dict="$dict")
    log=$STORE/$target/last.log
    # Fork mode runs its jobs in the working directory: the target's own.
    # ASan records no allocation stacks (malloc_context_size=0): a third of
    # the argument target's time went to them, and a finding is replayed for
    # its whole report anyway.
    (cd "$STORE/$target" &&
        ASAN_OPTIONS=malloc_context_size=0 LSAN_OPTIONS=suppressions=$ROOT/tests/fuzz/lsan.supp \
            "$fuzzer" "${options[@]}" "$corpus" >"$log" 2>&1) || true
    # Fork mode's progress lines: "#<executions>: cov: C ft: F corp: N exec/s: ..."
    last=$(grep -E '^#[0-9]+: cov: ' "$log" | tail -n 1)
    executions=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
    cov=$(sed -E 's/.* cov: ([0-9]+).*/\1/' <<<"$last")
    ft=$(sed -E 's/.* ft: ([0-9]+).*/\1/' <<<"$last")
    found=$(find "$findings" -maxdepth 1 -type f | wc -l)
    line=$(printf '%s %-9s %6ss executions %10s cov %6s ft %6s corpus %6s findings %s' \
        "$(date -u +%Y-%m-%dT%H:%MZ)" "$target" "$SECONDS_PER_TARGET" "${executions:-0}" \
        "${cov:-?}" "${ft:-?}" "$(find "$corpus" -type f | wc -l)" "$found")
    echo "$line" | tee -a "$STORE/campaign.log"
done
