#!/usr/bin/env bash
# The memory of a layer range: `strata slice --layers` holds a bounded window of layers (a batch
# of computed layers, their classes, and the shell's reach on each side), never the range or the
# grid, so its peak resident memory does not grow with the range's length nor with the grid's
# layer count. Measured here with GNU time on the sand mould of tools/make_sand_mould.mjs at
# 1.5 mm cells (1200 x 667 cells a layer, 0.8 MB), against what holding the range would cost, and
# against the bound: a run that holds no layer (one layer of 36 x 20 cells) plus 128 layers.
#
# Usage: tests/scale/range_memory_test.sh STRATA NODE
set -euo pipefail

die() {
  echo "range memory test: FAIL: $*" >&2
  exit 1
}
[ $# -eq 2 ] || die "usage: range_memory_test.sh STRATA NODE"
strata="$1"
node_js="$2"
repo="$(cd "$(dirname "$0")/../.." && pwd)"
[ -x /usr/bin/time ] || die "/usr/bin/time (GNU time) not found: \`bash scripts/setup.sh test\` installs it"

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
"$node_js" "$repo/tools/make_sand_mould.mjs" "$scratch/mould.stl" 64 > /dev/null

# A sanitizer build keeps freed memory in quarantine for a while; keep that small, so that what is
# measured is what the slicer holds.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}quarantine_size_mb=8:thread_local_quarantine_size_kb=64"

layer_bytes=$((1200 * 667))  # a byte a cell
# Peak resident memory, in bytes, of one `slice --layers` run: NAME CELL LAYER RANGE.
peak() {
  local name="$1" cell="$2" layer="$3" range="$4"
  /usr/bin/time -f %M -o "$scratch/$name.kib" "$strata" slice "$scratch/mould.stl" \
    --cell "$cell" --layer "$layer" --layers "$range" --format cells --threads 2 \
    -o "$scratch/$name" --quiet || die "slice --cell $cell --layer $layer --layers $range failed"
  echo $(($(tail -n 1 "$scratch/$name.kib") * 1024))
}
base="$(peak base 50 50 7)"              # one layer of 36 x 20 cells: the mesh, the runtime
short="$(peak short 1.5 1.5 200:210)"    # 10 layers of 467
long="$(peak long 1.5 1.5 100:400)"      # 300 layers of 467
tall="$(peak tall 1.5 0.25 1200:1210)"   # 10 layers of 2800
mib() { echo "$(($1 / 1048576)) MiB"; }
echo "range memory test: peak memory without layers $(mib "$base"); 10 layers of 467:" \
  "$(mib "$short"); 300 layers of 467: $(mib "$long"); 10 layers of 2800: $(mib "$tall")" \
  "(a layer: $((layer_bytes / 1024)) KiB)"

# The window: at most 32 computed layers, their classes, the shell's reach and the threads'
# scratch, some 94 layers here. Holding the range would add 290 layers to the long run.
[ "$long" -lt $((short + 100 * layer_bytes)) ] ||
  die "300 layers took $(mib "$long") against $(mib "$short") for 10: memory grows with the range"
[ "$tall" -lt $((short + 100 * layer_bytes)) ] ||
  die "10 layers of a 2800-layer grid took $(mib "$tall") against $(mib "$short") in one of 467"
for run in short long tall; do
  [ "${!run}" -le $((base + 128 * layer_bytes)) ] ||
    die "$run: $(mib "${!run}") is over the bound, $(mib "$base") + 128 layers"
done
# The cells are there too: the long range's file holds its 300 layers.
"$strata" info "$scratch/long/mould.cells" > "$scratch/long.info"
grep -q '^grid *1200 x 667 x 300 cells' "$scratch/long.info" ||
  die "long/mould.cells: not 1200 x 667 x 300 cells: $(cat "$scratch/long.info")"
echo "range memory test: memory does not grow with the range nor with the grid's layers"
