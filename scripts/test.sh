#!/usr/bin/env bash
# From a fresh Debian 12 machine: install what is missing (clang and its sanitizer runtimes
# included), build the `asan` preset (clang -O1, AddressSanitizer + UndefinedBehaviorSanitizer,
# warnings as errors) and run the whole test suite under it through CTest (unit, property and
# corpus tests, and the quick validation run). Any sanitizer report fails the test it occurs in.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh test
bash scripts/build.sh asan
ctest --preset asan || { bash scripts/failure_digest.sh build/asan; exit 1; }
bash scripts/skipped_digest.sh build/asan
