#!/usr/bin/env bash
# Prints, after a failed CTest run, the lines of each failing test's output that say why (a
# failed assertion, a sanitizer report, a browser test's "not ok" with its error), so that the
# end of a long log names the cause. Usage: scripts/failure_digest.sh BUILD_DIR
set -uo pipefail
temporary="$1/Testing/Temporary"
[ -f "$temporary/LastTestsFailed.log" ] || exit 0
echo
echo "=== why the failing tests failed (from $temporary/LastTest.log) ==="
while IFS=: read -r _ name; do
  echo "--- $name"
  # The test's section of the log: from its "Test: NAME" line to its "Test Failed" line.
  section=$(awk -v name="$name" '
    $0 ~ "^[0-9]+/[0-9]+ Test: " && substr($0, index($0, "Test: ") + 6) == name { inside = 1 }
    inside { print }
    inside && /^Test (Failed|Passed)|^"[^"]*" end time/ { inside = 0 }
  ' "$temporary/LastTest.log")
  why=$(grep -E -A14 'not ok |\[  FAILED  \]|Failure$|error: |AddressSanitizer|runtime error|Timeout|Expected|Which is|FAIL' <<< "$section" |
    grep -v -E '^\s*(duration_ms|type|\.\.\.|---|ok [0-9]+ |# Subtest)' | head -n 24)
  # A script's test says why in its own words, usually last.
  if [ -n "$why" ]; then echo "$why"; else grep -v -E '^(Test time|Test Failed|"[^"]*" end time|-+$)' <<< "$section" | tail -n 12; fi
done < "$temporary/LastTestsFailed.log"
