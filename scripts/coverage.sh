#!/usr/bin/env bash
# Line and branch coverage of the library by the unit and property tests (strata_tests; not the
# corpus tests, not the browser test): builds the `coverage` preset (clang -O0 with
# -fprofile-instr-generate -fcoverage-mapping), runs the tests through `ctest --preset coverage`
# (every process, the strata executable the CLI tests start included, writes
# build/coverage/profiles/<pid>-<binary>.profraw), merges the profiles with llvm-profdata-14 and
# prints a markdown table per module of src/ (src/<m>/ and include/strata/<m>/; src/cli/ and the
# sources generated under build/ left out), with a total row.
# Usage: scripts/coverage.sh [--no-build]   (the summary JSON stays in build/coverage/coverage.json)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/coverage

if [ "${1:-}" != "--no-build" ]; then
  bash scripts/setup.sh coverage
  cmake --preset coverage > /dev/null
  cmake --build --preset coverage -j "$(nproc)"
fi

rm -rf "$build/profiles"
mkdir -p "$build/profiles"
ctest --preset coverage --progress
llvm-profdata-14 merge -sparse "$build"/profiles/*.profraw -o "$build/coverage.profdata"
rm -rf "$build/profiles"
llvm-cov-14 export -summary-only -instr-profile="$build/coverage.profdata" \
  "$build/tests/strata_tests" -object "$build/src/strata" > "$build/coverage.json"

python3 - "$build/coverage.json" "$PWD" << 'EOF'
import json
import os
import sys

report, root = sys.argv[1], os.path.realpath(sys.argv[2])
modules = {}
for data in json.load(open(report))["data"]:
    for f in data["files"]:
        path = os.path.relpath(os.path.realpath(f["filename"]), root)
        parts = path.split(os.sep)
        if parts[:1] == ["src"] and len(parts) > 2:
            module = parts[1]
        elif parts[:2] == ["include", "strata"] and len(parts) > 3:
            module = parts[2]
        else:
            continue  # tests, third-party headers, build/ (the generated page sources), the facade
        if module == "cli":
            continue
        counts = modules.setdefault(module, [0, 0, 0, 0])
        s = f["summary"]
        counts[0] += s["lines"]["covered"]
        counts[1] += s["lines"]["count"]
        counts[2] += s["branches"]["covered"]
        counts[3] += s["branches"]["count"]

def row(name, c):
    def cell(covered, total):
        percent = f"{100.0 * covered / total:.1f} %" if total else "-"
        return f"{covered} / {total} | {percent}"
    return f"| {name} | {cell(c[0], c[1])} | {cell(c[2], c[3])} |"

print("| module | lines | % | branches | % |")
print("|---|---:|---:|---:|---:|")
for name in sorted(modules):
    print(row(f"`{name}/`", modules[name]))
print(row("**total**", [sum(c[i] for c in modules.values()) for i in range(4)]))
EOF
