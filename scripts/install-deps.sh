#!/usr/bin/env bash
# Installs what building and testing libpolymass needs (Debian/Ubuntu).
# Idempotent: asks dpkg what is missing and runs apt-get (update once, then
# install) only when something is. Non-interactive; sudo only when not root.
#
#   scripts/install-deps.sh [extra-package...]
set -euo pipefail

packages=(
    cmake ninja-build g++ gcc pkg-config   # toolchain
    ccache                                 # test command: compiles cached across runs and clones
    libeigen3-dev                          # the library's (private) dependency
    libcmocka-dev                          # unit tests
    libbullet-dev                          # examples/bullet: a rigid body for Bullet
    clang-format                           # style check
    clang libclang-rt-14-dev               # fuzz preset: clang, libFuzzer + sanitizer runtimes
    llvm                                   # coverage preset: llvm-profdata, llvm-cov
    abigail-tools binutils                 # ABI gate (abidw, abidiff), nm, readelf
    dpkg-dev file                          # dpkg-buildpackage, dpkg-shlibdeps
    python3 python3-venv                   # Python binding: a venv with cffi, pytest from PyPI
    libclang-dev                           # Rust binding: bindgen's libclang
    libcli11-dev nlohmann-json3-dev libpugixml-dev   # the polymass CLI: arguments, JSON, XML
    libtinygltf-dev                        # the polymass CLI: glTF/GLB reader
    libzip-dev                             # the polymass CLI: 3MF packages (their model through pugixml)
    libassimp-dev                          # the polymass CLI: Collada (.dae) reader
    libjs-three                            # the polymass CLI: three.js, embedded in --html pages
    chromium                               # tests/browser: the --html pages in headless Chromium
    debhelper lintian help2man             # the Debian package (debian/): dh, lintian, its man page
    "$@"
)

missing=()
for package in "${packages[@]}"; do
    # dpkg -s succeeds for removed-but-configured packages too: check the status.
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q '^install ok installed$'; then
        missing+=("$package")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

if ! command -v apt-get >/dev/null 2>&1; then
    echo "install-deps: missing ${missing[*]} and no apt-get here: install them by hand" >&2
    exit 1
fi
sudo=()
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
        sudo=(sudo -n)
    else
        echo "install-deps: missing ${missing[*]}; not root and no sudo" >&2
        exit 1
    fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    "${missing[@]}" </dev/null
