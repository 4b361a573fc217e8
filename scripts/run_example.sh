#!/usr/bin/env bash
# From a fresh Debian 12 machine: install what is missing, build in Release, and slice the
# sample ring with the default settings.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release
mkdir -p out
./build/release/src/strata slice data/ring.stl -o out/ring-strata
echo
./build/release/src/strata info out/ring-strata/ring.cells
