#!/usr/bin/env bash
# Slices a model through scripts/slurm/submit.sh on a one-node Slurm cluster started here, on
# localhost, and checks that the merged result equals a whole run of the same model and options:
# every file byte for byte, the JSON report but for what a merge documents as its own
# (`timings_s`, `merged_from`, the whole run's `plan`).
#
# Usage: tests/slurm/slurm_array_test.sh STRATA NODE MODEL --parts N --threads T [slice options]
#   STRATA  the strata executable; NODE  node.js (compares the reports)
#   --threads T  for the whole run and every task alike (the report records the threads)
# Needs Debian's slurm-wlm and munge (`bash scripts/setup.sh test` installs them) and root, as
# slurmd runs jobs as their users. Nothing is installed or left behind: munged, slurmctld and
# slurmd run from a scratch folder (their keys, sockets, state, logs, configuration) on ports
# found free, and are stopped, and the folder removed, whatever happens. It never skips: a
# cluster that does not start fails the test with the daemons' logs.
# Environment: STRATA_SLURM_TIMEOUT, seconds the jobs may take (default 150: with the 90 s the
# cluster may take to start and 30 s to stop, under the 300 s CTest gives the test).
set -euo pipefail

die() {
  echo "slurm test: FAIL: $*" >&2
  exit 1
}
[ $# -ge 3 ] || die "usage: slurm_array_test.sh STRATA NODE MODEL --parts N [slice options]"
strata="$(realpath "$1")"
node_js="$2"
model="$(realpath "$3")"
shift 3
slice_args=("$@")  # --parts N and the slice options, as submit.sh takes them
[[ " $* " == *" --threads "* ]] || die "give --threads T: the reports record it, so both runs need the same"
repo="$(cd "$(dirname "$0")/../.." && pwd)"
job_timeout="${STRATA_SLURM_TIMEOUT:-150}"

[ -x "$strata" ] || die "$strata: not an executable"
[ -f "$model" ] || die "$model: no such file"
if [ "$(id -u)" -ne 0 ]; then
  # slurmd starts jobs as their users, so the cluster runs as root: through sudo when the test
  # does not (scripts/setup.sh installs its packages with sudo the same way).
  sudo -n true 2> /dev/null || die "needs root, or sudo without a password: slurmd starts jobs as their users"
  exec sudo -n --preserve-env=STRATA_SLURM_TIMEOUT,PATH "$0" "$strata" "$node_js" "$model" "$@"
fi
for c in munged munge unmunge slurmctld slurmd sinfo sbatch scontrol squeue scancel ss; do
  command -v "$c" > /dev/null ||
    die "$c not found: \`bash scripts/setup.sh test\` installs slurm-wlm and munge"
done

scratch="$(mktemp -d /tmp/strata-slurm.XXXXXX)"
pids=()  # the daemons started here, in start order
failed=1
cleanup() {
  local rc=$?
  set +e
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ] && [ ${#pids[@]} -ge 2 ]; then
    scancel --quiet --full --signal=KILL --user=root 2> /dev/null  # jobs still queued or running
  fi
  # slurmd, slurmctld, munged: TERM, then KILL what is still there after 10 s.
  local i pid t
  for ((i = ${#pids[@]} - 1; i >= 0; --i)); do
    pid="${pids[i]}"
    kill -TERM "$pid" 2> /dev/null || continue
    for ((t = 0; t < 100; ++t)); do
      kill -0 "$pid" 2> /dev/null || break
      sleep 0.1
    done
    kill -KILL "$pid" 2> /dev/null
    wait "$pid" 2> /dev/null
  done
  if ((failed)) || [ "$rc" -ne 0 ]; then
    for f in "$scratch"/log/*; do
      [ -f "$f" ] || continue
      echo "----- $f (last 60 lines)" >&2
      tail -n 60 "$f" >&2
    done
  fi
  rm -rf "$scratch"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Polls CONDITION (a command) every 0.2 s for at most SECONDS; fails with WHAT when it never holds.
# Also fails at once when a daemon started here has died.
wait_for() {
  local seconds="$1" what="$2"
  shift 2
  local deadline=$((SECONDS + seconds)) pid
  until "$@"; do
    for pid in "${pids[@]}"; do
      kill -0 "$pid" 2> /dev/null || die "a daemon (pid $pid) died while waiting for $what"
    done
    ((SECONDS < deadline)) || die "timed out after ${seconds}s waiting for $what"
    sleep 0.2
  done
}

mkdir -p "$scratch"/{munge,socket,log,run,state,spool,out}
# munged wants its key private and the folders on its socket's path open to every user.
chmod 755 "$scratch" "$scratch/socket"
chmod 700 "$scratch/munge"

# MUNGE: its own key, socket, pid and seed files, log.
sock="$scratch/socket/munge.socket"
dd if=/dev/urandom of="$scratch/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$scratch/munge/munge.key"
munged --foreground --socket="$sock" --key-file="$scratch/munge/munge.key" \
  --pid-file="$scratch/run/munged.pid" --seed-file="$scratch/munge/munged.seed" \
  --log-file="$scratch/log/munged.log" > "$scratch/log/munged.out" 2>&1 &
pids+=($!)
munge_works() { munge -n -S "$sock" 2> /dev/null | unmunge -S "$sock" > /dev/null 2>&1; }
wait_for 30 "munged to answer on $sock" munge_works

# Two free TCP ports: Slurm's own (6817, 6818) when free, else the first free pair above 16817.
listening="$(ss -ltnH | awk '{print $4}' | sed 's/.*://' | sort -u)"
port_free() { ! grep -qx "$1" <<< "$listening"; }
ctld_port=6817
until port_free "$ctld_port" && port_free "$((ctld_port + 1))"; do
  if [ "$ctld_port" -lt 16817 ]; then ctld_port=16817; else ctld_port=$((ctld_port + 2)); fi
  [ "$ctld_port" -lt 17817 ] || die "no two free ports found"
done
slurmd_port=$((ctld_port + 1))

# The node: this machine's short hostname, reached at 127.0.0.1 (no name resolution needed),
# with the CPUs, sockets and memory slurmd finds.
node="$(hostname -s)"
hw="$(slurmd -C | head -n 1)"
[[ "$hw" == NodeName=* ]] || die "slurmd -C printed '$hw'"
hw="${hw#NodeName=* }"
export SLURM_CONF="$scratch/slurm.conf"
: > "$scratch/plugstack.conf"
cat > "$SLURM_CONF" << CONF
ClusterName=strata-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/run/slurmctld.pid
SlurmdPidFile=$scratch/run/slurmd.pid
SlurmctldLogFile=$scratch/log/slurmctld.log
SlurmdLogFile=$scratch/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$scratch/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SlurmdParameters=config_overrides
ReturnToService=2
MinJobAge=600
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 $hw State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -D -f "$SLURM_CONF" > "$scratch/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" > "$scratch/log/slurmd.out" 2>&1 &
pids+=($!)
node_idle() { [ "$(sinfo -h -N -n "$node" -o '%T' 2> /dev/null)" = idle ]; }
wait_for 60 "node $node to be idle in sinfo" node_idle
echo "slurm test: cluster up (node $node, ports $ctld_port/$slurmd_port, $hw)"

# The array job and its merge, through the documented script.
out="$scratch/out/run"
STRATA="$strata" bash "$repo/scripts/slurm/submit.sh" "$model" "$out" "${slice_args[@]}"
# shellcheck source=/dev/null
. "$out/jobs.env"
[[ "${ARRAY_JOB:-}" =~ ^[0-9]+$ && "${MERGE_JOB:-}" =~ ^[0-9]+$ ]] || die "$out/jobs.env: no job ids"

# The whole run to compare with, on this machine while the jobs run. submit.sh's options but
# --parts and what follows `--` (sbatch's).
whole_args=()
skip_next=0
for a in "${slice_args[@]}"; do
  if ((skip_next)); then skip_next=0; continue; fi
  case "$a" in
    --) break ;;
    --parts) skip_next=1 ;;
    --parts=*) ;;
    *) whole_args+=("$a") ;;
  esac
done
# Without --format the parts write cells,png,json (a range's default) and so does the merge.
[[ " ${whole_args[*]} " == *" --format "* ]] || whole_args+=(--format "cells,png,json")
"$strata" slice "$model" -o "$scratch/out/whole" --quiet "${whole_args[@]}"

job_states() { scontrol show job -o "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | sed 's/JobState=//'; }
merge_ended() {
  case "$(job_states "$MERGE_JOB")" in
    COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE | PREEMPTED) return 0 ;;
    *) return 1 ;;
  esac
}
wait_for "$job_timeout" "merge job $MERGE_JOB to end" merge_ended
array_states="$(job_states "$ARRAY_JOB" | sort | uniq -c | tr -s ' \n' '  ')"
merge_state="$(job_states "$MERGE_JOB")"
echo "slurm test: array job $ARRAY_JOB tasks:$array_states; merge job $MERGE_JOB: $merge_state"
if [ "$merge_state" != COMPLETED ] || job_states "$ARRAY_JOB" | grep -vqx COMPLETED; then
  for f in "$out"/logs/*; do echo "----- $f" >&2; cat "$f" >&2; done
  die "the jobs did not all complete"
fi
n_parts="$(wc -l < "$out/ranges.txt")"
[ "$(job_states "$ARRAY_JOB" | wc -l)" -eq "$n_parts" ] || die "the array job has not $n_parts tasks"

# The merged folder against the whole run: the same files, each byte for byte but the report.
whole="$scratch/out/whole"
merged="$out/merged"
(cd "$whole" && find . -type f | sort) > "$scratch/whole.list"
(cd "$merged" && find . -type f | sort) > "$scratch/merged.list"
diff -u "$scratch/whole.list" "$scratch/merged.list" > /dev/null ||
  die "the merged folder has other files than the whole run's: $(diff "$scratch/whole.list" "$scratch/merged.list" | head -20)"
grep -q '\.cells$' "$scratch/whole.list" || die "no .cells file in the whole run's outputs"
n_files=0
while read -r f; do
  case "$f" in
    *.json)
      "$node_js" -e '
        const fs = require("fs"), assert = require("assert");
        const [w, m, parts] = [JSON.parse(fs.readFileSync(process.argv[1])),
                               JSON.parse(fs.readFileSync(process.argv[2])), +process.argv[3]];
        assert.strictEqual(m.merged_from.length, parts, "merged_from lists every part");
        for (const k of ["timings_s", "merged_from", "plan"]) { delete w[k]; delete m[k]; }
        assert.deepStrictEqual(m, w);' "$whole/$f" "$merged/$f" "$n_parts" ||
        die "$f: the merged report differs from the whole run's"
      ;;
    *) cmp "$whole/$f" "$merged/$f" || die "$f: the merged file differs from the whole run's" ;;
  esac
  n_files=$((n_files + 1))
done < "$scratch/whole.list"
echo "slurm test: merged output of $n_parts Slurm array tasks equals the whole run ($n_files files)"
failed=0
