#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (preset `asan`: clang, AddressSanitizer +
# UndefinedBehaviorSanitizer) and runs each for SECONDS on a copy of its seed corpus under
# build/asan/fuzz-run/ (the repository is never written). Fails when a target finds a crash, a
# leak, a timeout or an out-of-memory input; the input is left in
# build/asan/fuzz-run/<target>/artifacts/.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]   (default 60 seconds, every target)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(fuzz_stl_binary fuzz_stl_ascii fuzz_obj fuzz_off fuzz_ply fuzz_cells fuzz_3mf_assembly
           fuzz_slice_kernels fuzz_serve_route fuzz_slice_options)
fi

bash scripts/setup.sh sanitizers
cmake --preset asan > /dev/null
cmake --build --preset asan --target strata_fuzzers -j "$(nproc)"

export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
run_root=build/asan/fuzz-run

# One target: its run's status is left in $dir/status, its log in $dir/log.
run_target() {
  local t="$1" dir="$run_root/$1"
  rm -rf "$dir"
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp fuzz/corpus/"$t"/* "$dir/corpus/"
  local args=("$dir/corpus" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048
              -max_len=65536 -print_final_stats=1 -artifact_prefix="$dir/artifacts/")
  local dict="fuzz/${t#fuzz_}.dict"
  if [ -f "$dict" ]; then args+=(-dict="$dict"); fi
  local status=0
  "build/asan/fuzz/$t" "${args[@]}" > "$dir/log" 2>&1 || status=$?
  echo "$status" > "$dir/status"
}

# A target runs on one core: as many at once as there are cores, each for its full time.
parallel="$(nproc)"
echo "strata fuzz: ${#targets[@]} target(s) for ${seconds}s each, ${parallel} at a time"
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  run_target "$t" &
done
wait

failed=()
for t in "${targets[@]}"; do
  dir="$run_root/$t"
  if [ "$(cat "$dir/status")" = 0 ]; then
    echo "strata fuzz: $t: $(grep -E '^#[0-9]+[[:space:]]+DONE' "$dir/log" | tail -1)"
  else
    echo "strata fuzz: $t FAILED; the input is in $dir/artifacts/, the log in $dir/log:"
    grep -E -A 30 'ERROR: |runtime error|fuzz check failed|deadly signal|timeout|out-of-memory' \
      "$dir/log" | head -60 || tail -40 "$dir/log"
    failed+=("$t")
  fi
done

if ((${#failed[@]})); then
  echo "strata fuzz: ${#failed[@]} target(s) failed: ${failed[*]}"
  exit 1
fi
echo "strata fuzz: ${#targets[@]} target(s) ran ${seconds}s each without a finding"
