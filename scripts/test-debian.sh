#!/usr/bin/env bash
# Builds the Debian packages from debian/ and checks them:
#   1. copies the source tree (the files git tracks, plus new files it does not
#      ignore) to ~/.cache/polymass/debian/polymass-<version>/, so that
#      dpkg-buildpackage, which writes its packages into the parent directory
#      and its build tree into the source, leaves the working tree clean. The
#      place is the same for every clone: dpkg-buildflags writes the source
#      directory into the compiler flags (-ffile-prefix-map=DIR=.), and ccache
#      finds an earlier build's objects only under the same flags;
#   2. dpkg-buildpackage -us -uc -b (binary packages, unsigned): the cmake
#      build through dh, the symbols check against debian/libpolymass2.symbols,
#      the manual page from `polymass --help`;
#   3. lintian on the result: any error or warning fails (the full output is
#      printed, informational tags and overridden ones included);
#   4. unpacks the three packages into a scratch root, checks that the library
#      package libpolymassN ships SONAME libpolymass.so.N (N the major
#      version), and runs the packaged tool, with the packaged library, on the
#      bundled bracket.
#
#   scripts/test-debian.sh
#
# Non-interactive; assumes scripts/install-deps.sh ran (debhelper, lintian,
# help2man and the build dependencies of debian/control).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
version=$(dpkg-parsechangelog -S Version)
work=${XDG_CACHE_HOME:-$HOME/.cache}/polymass/debian
source_dir=$work/polymass-$version

step() { printf '\n==================== debian: %s ====================\n' "$1"; }

step source
rm -rf "$work"
mkdir -p "$source_dir"
git ls-files -z --cached --others --exclude-standard |
    while IFS= read -r -d '' file; do [ -e "$file" ] && printf '%s\0' "$file"; done |
    tar --null --files-from=- -cf - | tar -xf - -C "$source_dir"
echo "copied to $source_dir"

step build
# debhelper runs the build with HOME set to a scratch directory inside the
# package tree, where ccache would keep (and lose with the tree) a cache of
# its own: name the user's cache, so that the test command's compiler cache
# serves this build too.
if command -v ccache >/dev/null 2>&1 && [ -z "${CCACHE_DIR:-}" ]; then
    CCACHE_DIR=$(ccache -k cache_dir)
    export CCACHE_DIR
fi
(cd "$source_dir" && dpkg-buildpackage -us -uc -b -j"${CMAKE_BUILD_PARALLEL_LEVEL:-2}" </dev/null)
changes=$(ls "$work"/polymass_"$version"_*.changes)
ls -l "$work"/*.deb

step lintian
lintian --display-info --show-overrides --fail-on error,warning "$changes"
echo "lintian: no errors, no warnings"

step smoke
scratch=$work/root
for deb in "$work"/*.deb; do
    dpkg-deb -x "$deb" "$scratch"
done
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH)
# The shared library's package is named after its SONAME (Debian policy 8.1):
# libpolymassN ships libpolymass.so.N, N the project's major version.
major=${version%%.*}
test -f "$work"/libpolymass"$major"_"$version"_*.deb
soname=$(readelf -d "$scratch/usr/lib/$multiarch/libpolymass.so" | sed -nE 's/.*\(SONAME\).*\[(.*)\]/\1/p')
if [ "$soname" != "libpolymass.so.$major" ]; then
    echo "FAIL: the packaged library's SONAME is '$soname', not libpolymass.so.$major" >&2
    exit 1
fi
echo "SONAME $soname in package libpolymass$major"
test -f "$scratch/usr/share/man/man1/polymass.1.gz"
LD_LIBRARY_PATH=$scratch/usr/lib/$multiarch "$scratch/usr/bin/polymass" \
    examples/data/bracket.obj --units mm --density 2700

echo
echo "test-debian: all passed"
