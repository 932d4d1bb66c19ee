#!/usr/bin/env bash
# The main job: install the dependencies, build the release preset, and run
# the polymass tool on a mesh bundled with the project: an aluminium L-bracket
# drawn in millimetres (examples/data/bracket.obj), reported in SI units.
#
#   scripts/run.sh
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
./build/release/src/cli/polymass examples/data/bracket.obj --units mm --density 2700
