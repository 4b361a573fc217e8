#!/usr/bin/env bash
# Line and branch coverage of the library by the unit and property tests (strata_tests; not the
# corpus tests, not the browser test): builds the `coverage` preset (clang -O0 with
# -fprofile-instr-generate -fcoverage-mapping), runs the tests through `ctest --preset coverage`
# (every process, the strata executable the CLI tests start included, writes
# build/coverage/profiles/<binary>.profraw, the processes of one binary merging into one file), merges the profiles with llvm-profdata-14 and
# prints a markdown table per module of src/ (src/<m>/ and include/strata/<m>/; src/cli/ and the
# sources generated under build/ left out), with a total row.
# Usage: scripts/coverage.sh [--no-build]   (the lcov data stays in build/coverage/coverage.lcov)
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
# One line a test would bury the table: the log stays in build/coverage/ctest.log.
if ! ctest --preset coverage > "$build/ctest.log"; then
  tail -n 40 "$build/ctest.log"
  exit 1
fi
grep -E "tests passed|Total Test time" "$build/ctest.log"
llvm-profdata-14 merge -sparse "$build"/profiles/*.profraw -o "$build/coverage.profdata"
rm -rf "$build/profiles"
# lcov records rather than the JSON summary: a header reached through two spellings of its path
# (include/… and build/coverage/../../include/…, as ccache's base-dir rewriting leaves them) is
# one file here, its lines and branches merged.
llvm-cov-14 export -format=lcov -instr-profile="$build/coverage.profdata" \
  "$build/tests/strata_tests" -object "$build/src/strata" > "$build/coverage.lcov"

python3 - "$build/coverage.lcov" "$PWD" << 'EOF'
import os
import sys

report, root = sys.argv[1], os.path.realpath(sys.argv[2])


def module_of(path):
    """src/<m>/... and include/strata/<m>/... are module m; None for anything else (the tests,
    third-party headers, the sources generated under build/, the facade, the command line)."""
    parts = os.path.relpath(os.path.realpath(path), root).split(os.sep)
    if parts[:1] == ["src"] and len(parts) > 2:
        module = parts[1]
    elif parts[:2] == ["include", "strata"] and len(parts) > 3:
        module = parts[2]
    else:
        return None
    return None if module == "cli" else module


files = {}  # real path -> ({line: hit}, {(line, n-th branch of the line): taken})
current = None
for text in open(report):
    text = text.strip()
    if text.startswith("SF:"):
        path = os.path.realpath(text[3:])
        current = files.setdefault(path, ({}, {})) if module_of(path) else None
        branch_index = {}
    elif current is None:
        continue
    elif text.startswith("DA:"):
        line, count = (int(v) for v in text[3:].split(",")[:2])
        current[0][line] = current[0].get(line, False) or count > 0
    elif text.startswith("BRDA:"):
        line, _, _, taken = text[5:].split(",")
        line = int(line)
        key = (line, branch_index.get(line, 0))
        branch_index[line] = key[1] + 1
        current[1][key] = current[1].get(key, False) or taken not in ("-", "0")

modules = {}
for path, (lines, branches) in files.items():
    counts = modules.setdefault(module_of(path), [0, 0, 0, 0])
    counts[0] += sum(lines.values())
    counts[1] += len(lines)
    counts[2] += sum(branches.values())
    counts[3] += len(branches)


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
