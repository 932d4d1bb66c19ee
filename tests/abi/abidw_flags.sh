# Sourced by abi_gate.sh and update_baseline.sh: how libpolymass.so is dumped.
# Only what the exported functions reach and the public header defines counts
# (--exported-interfaces-only, --headers-dir, --drop-private-types: no Eigen,
# no std::, no private struct bodies), and nothing machine-specific goes into
# the dump (no locations, no build paths), so the committed baseline is stable.
# shellcheck shell=bash
polymass_abidw_dump() { # <abidw> <libpolymass.so> <source root> <output.abi>
    local abidw=$1 library=$2 root=$3 out=$4
    "$abidw" --no-corpus-path --no-comp-dir-path --no-show-locs \
        --exported-interfaces-only --drop-private-types \
        --headers-dir "$root/include/polymass" \
        --out-file "$out.tmp" "$library" || return 1
    # Translation units are named by their absolute path: keep it relative.
    sed -e "s|path='$root/|path='|g" "$out.tmp" >"$out" && rm -f "$out.tmp"
}
