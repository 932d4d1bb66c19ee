#!/usr/bin/env bash
# Regenerates tests/abi/libpolymass.abi, the baseline of the abi.abidiff test,
# from a built libpolymass.so. Run it after a deliberate ABI change and commit
# the result.
#
#   tests/abi/update_baseline.sh [path/to/libpolymass.so]
#
# Without an argument it builds the `dev` preset and uses build/dev's library.
# Any build with debug information (-g) gives the same dump.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
# shellcheck source=abidw_flags.sh
. "$here/abidw_flags.sh"

if [ $# -ge 1 ]; then
    library=$1
else
    cd "$root"
    cmake --preset dev >/dev/null
    cmake --build --preset dev --target polymass
    # The link, not a listing: a build tree keeps the libraries of earlier versions.
    library=$root/build/dev/src/libpolymass.so
fi
library=$(readlink -f "$library")
abidw=$(command -v abidw) || { echo "abidw not found (Debian: apt-get install abigail-tools)" >&2; exit 1; }

polymass_abidw_dump "$abidw" "$library" "$root" "$here/libpolymass.abi"
echo "wrote $here/libpolymass.abi from $library"
grep -c "<elf-symbol name='polymass_" "$here/libpolymass.abi" | sed 's/^/exported functions in the baseline: /'
