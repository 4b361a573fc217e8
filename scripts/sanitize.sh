#!/usr/bin/env bash
# Builds with AddressSanitizer + UndefinedBehaviorSanitizer (preset `asan`, RelWithDebInfo; any
# report stops the process) and runs the whole test suite under them through CTest (unit,
# property and corpus tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh asan
ctest --preset asan
