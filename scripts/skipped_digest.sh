#!/usr/bin/env bash
# Prints, after a CTest run, every GoogleTest test that skipped itself and why (its GTEST_SKIP
# message). CTest runs the tests a suite at a time (cmake/StrataTestGroups.cmake), so a skip
# inside a passing group would otherwise go unsaid. Usage: scripts/skipped_digest.sh BUILD_DIR
set -uo pipefail
log="$1/Testing/Temporary/LastTest.log"
[ -f "$log" ] || exit 0
echo
echo "=== tests that skipped themselves (from $log) ==="
awk '
  /: Skipped$/ { collecting = 1; why = ""; next }
  collecting && /^\[  SKIPPED \] [^ ]+ \(/ {
    printf "  %s: %s\n", $4, why; collecting = 0; count++; next
  }
  collecting { why = (why == "" ? $0 : why " " $0) }
  END {
    if (count == 0) print "no test skipped itself"
    else printf "%d test(s) skipped themselves, each with its reason above\n", count
  }
' "$log"
