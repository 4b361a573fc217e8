#!/usr/bin/env bash
# From a fresh Debian 12 machine: install what is missing, build with warnings as errors, and run
# the whole test suite through CTest (unit, property and corpus tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh ci
ctest --preset ci
