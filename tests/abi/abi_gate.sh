#!/usr/bin/env bash
# ctest abi.abidiff: the ABI of the built libpolymass.so against the committed
# baseline tests/abi/libpolymass.abi.
#
#   abi_gate.sh <abidw> <abidiff> <libpolymass.so> <baseline.abi> <source root> <work dir>
#
# Passes when the library only ADDS to the baseline (new functions, new
# variables). Fails on anything else abidiff reports: a removed symbol
# (ABIDIFF_ABI_INCOMPATIBLE_CHANGE, bit 8), or a change to a function or type
# the baseline has (bit 4 with something other than additions), or an abidiff
# error (bits 1, 2). After a deliberate ABI change (a new major version, or a
# struct that grew at its end, which abidiff reports as a change), regenerate
# the baseline with tests/abi/update_baseline.sh and commit it.
set -euo pipefail

if [ $# -ne 6 ]; then
    echo "usage: $0 <abidw> <abidiff> <libpolymass.so> <baseline.abi> <source root> <work dir>" >&2
    exit 2
fi
abidw=$1 abidiff=$2 library=$3 baseline=$4 root=$5 work=$6
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=abidw_flags.sh
. "$here/abidw_flags.sh"

mkdir -p "$work"
current=$work/libpolymass.current.abi
report=$work/abidiff.report.txt
polymass_abidw_dump "$abidw" "$library" "$root" "$current"

set +e
"$abidiff" --no-show-locs "$baseline" "$current" >"$report" 2>&1
rc=$?
set -e
cat "$report"
echo "abidiff exit code: $rc"

if (( rc & 3 )); then
    echo "FAIL: abidiff could not compare (error/usage bits set)" >&2
    exit 1
fi
if (( rc & 8 )); then
    echo "FAIL: incompatible ABI change against $baseline (e.g. a removed symbol)" >&2
    exit 1
fi
if (( rc & 4 )); then
    # Something differs. Acceptable only if it is nothing but additions: every
    # summary line ("Functions changes summary: 0 Removed, 0 Changed, 2 Added
    # functions", the same for variables and for symbols without debug info)
    # must report 0 Removed and 0 Changed.
    summaries=$(grep -E '^(Functions|Variables|Function symbols|Variable symbols) changes summary:' "$report" || true)
    if [ -z "$summaries" ]; then
        echo "FAIL: abidiff reported a change but no summary line could be read" >&2
        exit 1
    fi
    not_added=$(sed -nE 's/.*: ([0-9]+) Removed(, ([0-9]+) Changed)?.*/\1 \3/p' <<<"$summaries" |
        awk '{ s += $1 + $2 } END { print s + 0 }')
    if [ "$not_added" != 0 ]; then
        echo "FAIL: $not_added function(s)/variable(s) of the baseline $baseline were removed or changed." >&2
        echo "      A struct that grew at its end counts as a change: if the change is" >&2
        echo "      deliberate and compatible, run tests/abi/update_baseline.sh and commit" >&2
        echo "      tests/abi/libpolymass.abi with it." >&2
        exit 1
    fi
    echo "OK: only additions against the baseline (allowed within a major version)"
    exit 0
fi
echo "OK: the ABI is identical to the baseline"
