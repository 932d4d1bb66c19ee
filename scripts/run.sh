#!/usr/bin/env bash
# The main job: install the dependencies, build the release preset and run the
# C example (later: the command-line tool).
#
#   scripts/run.sh
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
./build/release/examples/c/mass_properties
