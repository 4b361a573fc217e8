#!/usr/bin/env bash
# Slices a model on a Slurm cluster: one array job whose tasks slice one layer range each
# (`strata slice --layers`), then a merge job that starts once every task has succeeded and
# joins the parts into exactly what one whole run writes (`strata merge`).
#
# Usage: scripts/slurm/submit.sh MODEL OUT_DIR --parts N [slice options] [-- sbatch options]
#   MODEL, OUT_DIR  on a file system that every node of the cluster sees (the paths are made
#                   absolute here); OUT_DIR must be absent or empty
#   --parts N       number of layer ranges, hence of array tasks (`strata plan` balances them)
#   slice options   those of `strata slice`, but not -o/--output or --layers (set here); the
#                   grid's options (--cell, --layer, --shell, --origin, ...) go to `strata plan`
#                   too. Without --format the parts write cells,png,json; a --format must
#                   include json (the merge reads each part's report).
#   sbatch options  after `--`: given to both sbatch calls (e.g. --partition=..., --time=...,
#                   --cpus-per-task=4; a task slices with --threads = its CPUs)
# Environment: STRATA, the strata executable on the nodes (default: `strata` on the PATH);
#   SBATCH_* input variables (SBATCH_PARTITION, SBATCH_TIMELIMIT, ...) as sbatch reads them.
#
# It writes OUT_DIR/plan.json (`strata plan --json`), OUT_DIR/ranges.txt (one `A:B` a line, line
# k+1 for task k), OUT_DIR/jobs.env (ARRAY_JOB=..., MERGE_JOB=...), and the jobs write
# OUT_DIR/parts/part_KKKK/ (task k's outputs), OUT_DIR/logs/ (their stdout and stderr) and
# OUT_DIR/merged/ (the result). A failed task cancels the merge job (--kill-on-invalid-dep).
set -euo pipefail

usage() {
  sed -n '6,17p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}
die() {  # MESSAGE [EXIT CODE]
  echo "strata-slurm: $1" >&2
  exit "${2:-1}"
}

here="$(cd "$(dirname "$0")" && pwd)"
strata="${STRATA:-strata}"
# A path (not a name looked up on the PATH) is made absolute: the jobs run in other folders.
if [[ "$strata" == */* ]]; then strata="$(cd "$(dirname "$strata")" && pwd)/$(basename "$strata")"; fi
command -v "$strata" > /dev/null || die "$strata: not found (set STRATA=/path/to/strata)"

[ $# -ge 2 ] || usage
model="$1"
out="$2"
shift 2
[ -f "$model" ] || die "$model: no such file"
model="$(cd "$(dirname "$model")" && pwd)/$(basename "$model")"

parts=""
slice_opts=()  # for every task's `strata slice`
plan_opts=()   # the subset `strata plan` takes: those that define the grid
sbatch_opts=()
has_format=0
has_json=0
while [ $# -gt 0 ]; do
  arg="$1"
  shift
  name="${arg%%=*}"
  inline=0
  [ "$name" != "$arg" ] && inline=1
  case "$name" in
    --)
      sbatch_opts=("$@")
      break
      ;;
    --parts)
      if ((inline)); then parts="${arg#*=}"; else
        [ $# -ge 1 ] || die "--parts needs a value" 2
        parts="$1"
        shift
      fi
      ;;
    -o | --output | --layers)
      die "$name is set by this script (OUT_DIR and the plan's ranges)" 2
      ;;
    -h | --help) usage ;;
    --layer | --cell | --dx | --dy | --shell | --shell-mode | --fill-rule | --scan-offset | \
      --threads | --units | --scale | --origin)
      count=1
      [ "$name" = --origin ] && count=3
      ((inline)) && count=0
      [ $# -ge "$count" ] || die "$name needs $count value(s)" 2
      slice_opts+=("$arg" "${@:1:count}")
      [ "$name" = --threads ] || plan_opts+=("$arg" "${@:1:count}")
      shift "$count"
      ;;
    --format)
      has_format=1
      if ((inline)); then value="${arg#*=}"; else
        [ $# -ge 1 ] || die "--format needs a value" 2
        value="$1"
        shift
      fi
      [[ ",$value," == *,json,* ]] && has_json=1
      slice_opts+=(--format "$value")
      ;;
    --kernel | --page-budget | --page-facets)
      if ((inline)); then slice_opts+=("$arg"); else
        [ $# -ge 1 ] || die "$name needs a value" 2
        slice_opts+=("$arg" "$1")
        shift
      fi
      ;;
    -q | --quiet | --repair | --fill-holes | --no-hatches)
      slice_opts+=("$arg")
      ;;
    *)
      die "unknown option '$arg' (see \`$strata slice --help\`)" 2
      ;;
  esac
done
[[ "$parts" =~ ^[1-9][0-9]*$ ]] || die "--parts N is required, N >= 1" 2
if ((has_format && !has_json)); then
  die "--format must include json: \`strata merge\` reads each part's report" 2
fi

command -v sbatch > /dev/null || die "sbatch not found: this runs on a Slurm submit host"
if [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then die "$out exists and is not empty"; fi
# The plan: balanced ranges of the whole model's layers (nothing is written when it fails).
plan="$("$strata" plan "$model" --parts "$parts" "${plan_opts[@]}" --json)" ||
  die "strata plan failed (its message is above)"
mkdir -p "$out/parts" "$out/logs"
out="$(cd "$out" && pwd)"
printf '%s\n' "$plan" > "$out/plan.json"
grep -o '"layers": *"[^"]*"' "$out/plan.json" | sed 's/.*"\([^"]*\)"$/\1/' > "$out/ranges.txt"
n="$(wc -l < "$out/ranges.txt")"
[ "$n" -eq "$parts" ] || die "$out/plan.json: expected $parts ranges, read $n"

# The array job: task k slices line k+1 of ranges.txt into parts/part_KKKK.
array_job="$(sbatch --parsable --array="0-$((n - 1))" \
  --output="$out/logs/slice_%A_%a.out" --error="$out/logs/slice_%A_%a.err" \
  "${sbatch_opts[@]}" --export="ALL,STRATA=$strata" \
  "$here/slice_part.sbatch" "$model" "$out" "${slice_opts[@]}")"
array_job="${array_job%%;*}"  # --parsable prints "id" or "id;cluster"
[[ "$array_job" =~ ^[0-9]+$ ]] || die "sbatch did not return a job id: '$array_job'"

# The merge job: once every task of the array has ended successfully.
merge_job="$(sbatch --parsable --dependency="afterok:$array_job" --kill-on-invalid-dep=yes \
  --output="$out/logs/merge_%j.out" --error="$out/logs/merge_%j.err" \
  "${sbatch_opts[@]}" --export="ALL,STRATA=$strata" \
  "$here/merge.sbatch" "$out")"
merge_job="${merge_job%%;*}"
[[ "$merge_job" =~ ^[0-9]+$ ]] || die "sbatch did not return a job id: '$merge_job'"

printf 'ARRAY_JOB=%s\nMERGE_JOB=%s\n' "$array_job" "$merge_job" > "$out/jobs.env"
echo "strata-slurm: array job $array_job ($n tasks, ranges in $out/ranges.txt)," \
  "merge job $merge_job -> $out/merged"
