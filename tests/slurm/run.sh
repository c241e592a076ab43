#!/usr/bin/env bash
# End-to-end test of scripts/slurm/submit-sweep on a one-node Slurm cluster started here, on
# localhost, from a private temporary directory (its own munged socket and key, slurm.conf, free
# ports, state, spool and logs); every daemon is stopped on exit.
#
#   tests/slurm/run.sh GYRORES SOURCE_DIR
#
# 0. A trivial job must run (else skip: this environment cannot launch jobs).
# 1. Shard 2 of 4 alone with --max-pairs 1000: the task stops with a resume state (exit 4), and
#    Slurm cancels the merge job (afterok never satisfied).
# 2. The plain submission of all 4 shards (--max-order 300): shard 2 resumes, the others run, the
#    merge job writes summary.json, which must equal a single local run of `gyrores sweep`.
# 3. Task 1 resubmitted alone: the complete shard is skipped and the merge gives the same summary.
# The summaries are compared byte for byte after removing the only run-specific fields
# (docs/formats.md "Merge"): `seconds` (compute time), `values_file`, `run.threads` and
# `run.merged_shards`; each is then printed canonically (sorted keys) and compared with cmp.
#
# About 15 s here (batch_sched_delay=0 lets dependent jobs start at once). Exit 0 pass, 1 fail,
# 77 skip with the reason: missing tools, not root, munged or a Slurm daemon not coming up, or
# a trivial job not running.
set -euo pipefail

[ $# -eq 2 ] || { echo "usage: run.sh GYRORES SOURCE_DIR" >&2; exit 2; }
gyrores=$(realpath "$1")
submit=$(realpath "$2")/scripts/slurm/submit-sweep
skip() { echo "SKIP: $*"; exit 77; }

for tool in sbatch squeue sinfo scontrol scancel slurmctld slurmd munged python3 flock; do
  command -v "$tool" >/dev/null || skip "'$tool' not found (scripts/setup installs slurm-wlm and munge)"
done
[ "$(id -u)" -eq 0 ] || skip "not root: slurmd must run as root to start jobs"
[ -x "$gyrores" ] || { echo "FAIL: '$gyrores' is not executable"; exit 1; }

T=$(mktemp -d "${TMPDIR:-/tmp}/gyrores-slurm.XXXXXX")
chmod 0700 "$T"
pids=()
t0=$SECONDS
log_tail() {
  for f in "$T"/munged.log "$T"/slurmctld.log "$T"/slurmd.log "$T"/out/logs/*.out; do
    [ -s "$f" ] || continue
    echo "--- ${f#"$T"/} (last 15 lines)"
    tail -n 15 "$f"
  done
}
fail() { echo "FAIL: $*"; log_tail; exit 1; }
cleanup() {
  local rc=$?
  set +e
  [ -z "${single_pid:-}" ] || kill "$single_pid" 2>/dev/null
  if [ -e "$T/slurm.conf" ] && [ ${#pids[@]} -ge 2 ]; then
    scancel -u root 2>/dev/null      # this private cluster's jobs only (SLURM_CONF)
    for _ in $(seq 50); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.2; done
  fi
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null; done
  for p in "${pids[@]+"${pids[@]}"}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null
    wait "$p" 2>/dev/null
  done
  rm -rf "$T"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The reference: one local run, in the background while the cluster starts.
"$gyrores" sweep --max-order 300 --quiet --summary "$T/single.json" > "$T/single.txt" 2>&1 &
single_pid=$!

# munged with a fresh key and its own socket (--force: it runs as root).
if command -v mungekey >/dev/null; then
  mungekey --create --keyfile="$T/munge.key" 2>"$T/mungekey.err" || skip "mungekey failed: $(cat "$T/mungekey.err")"
else
  dd if=/dev/urandom of="$T/munge.key" bs=1024 count=1 status=none
fi
chmod 0400 "$T/munge.key"
sock=$T/munge.sock
munged --foreground --force --socket="$sock" --key-file="$T/munge.key" --pid-file="$T/munged.pid" \
  --log-file="$T/munged.log" --seed-file="$T/munged.seed" 2>>"$T/munged.log" &
pids+=($!)
for _ in $(seq 50); do [ -S "$sock" ] && break; sleep 0.1; done
[ -S "$sock" ] || skip "munged did not start: $(tail -n 3 "$T/munged.log" 2>/dev/null | tr '\n' ' ')"
if command -v munge >/dev/null && command -v unmunge >/dev/null; then
  munge -n -S "$sock" | unmunge -S "$sock" >/dev/null 2>&1 || skip "munge credentials do not round-trip on $sock"
fi

# Two free TCP ports (bound, then released) for slurmctld and slurmd.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
ss = [socket.socket() for _ in range(2)]
for s in ss: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in ss])')

host=$(hostname -s 2>/dev/null || uname -n | cut -d. -f1)
mkdir -p "$T/state" "$T/spool"
cat > "$T/slurm.conf" <<EOF
ClusterName=gyrorestest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
KillWait=5
SchedulerParameters=batch_sched_delay=0,sched_min_interval=100000
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$T/slurm.conf

slurmctld -D -f "$SLURM_CONF" > "$T/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" > "$T/slurmd.out" 2>&1 &
pids+=($!)
node_state=''
for _ in $(seq 150); do
  node_state=$(sinfo -h -N -o '%T' 2>/dev/null || true)
  [ "$node_state" = idle ] && break
  for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null || break 2; done
  sleep 0.2
done
if [ "$node_state" != idle ]; then
  echo "SKIP: the one-node Slurm cluster did not come up (node state '${node_state:-none}')"
  cat "$T"/slurmctld.out "$T"/slurmd.out 2>/dev/null | tail -n 5
  log_tail
  exit 77
fi
echo "slurm: node $host idle after $((SECONDS - t0)) s (ports $ctld_port, $slurmd_port)"

# A trivial job first: if even that cannot run, the environment cannot launch jobs (skip).
canary=$(sbatch --parsable --output="$T/canary.out" --wrap 'echo canary ok' 2>&1) ||
  skip "sbatch refused a trivial job: $canary"
for _ in $(seq 150); do
  grep -q 'JobState=\(PENDING\|RUNNING\|CONFIGURING\|COMPLETING\)' <(scontrol -o show job "$canary" 2>&1) || break
  sleep 0.2
done
if ! grep -qx 'canary ok' "$T/canary.out" 2>/dev/null; then
  echo "SKIP: Slurm started but cannot run a trivial job here: $(scontrol -o show job "$canary" 2>&1 | grep -o 'JobState=[^ ]* Reason=[^ ]*')"
  log_tail
  exit 77
fi

# Waits until every job given is finished; prints "ID STATE" per job or array task.
wait_jobs() {
  local deadline=$((SECONDS + $1)) states
  shift
  while :; do
    states=$(for j in "$@"; do scontrol -o show job "$j" 2>/dev/null; done |
      sed -n 's/^JobId=[0-9]* ArrayJobId=\([0-9]*\) ArrayTaskId=\([0-9][-0-9,%]*\) .*JobState=\([A-Z_]*\).*/\1_\2 \3/p;
              /ArrayTaskId=/!s/^JobId=\([0-9]*\) .*JobState=\([A-Z_]*\).*/\1 \2/p')
    grep -qE ' (PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED|REQUEUED)' <<<"$states" || break
    [ $SECONDS -lt $deadline ] || fail "jobs $* not finished after $1 s: $(tr '\n' ' ' <<<"$states")"
    sleep 0.2
  done
  echo "$states"
}
# Submits with submit-sweep; sets array_job, merge_job.
submit() {
  local out
  out=$("$submit" --shards 4 --out-dir "$T/out" --gyrores "$gyrores" "$@") || fail "submit-sweep $* exited $?"
  echo "$out" | sed 's/^/  /'
  array_job=$(sed -n 's/^shards: job array \([0-9]*\).*/\1/p' <<<"$out")
  merge_job=$(sed -n 's/^merge:  job \([0-9]*\).*/\1/p' <<<"$out")
  [ -n "$array_job" ] && [ -n "$merge_job" ] || fail "no job ids in the output of submit-sweep"
}
core() {  # canonical summary without its run-specific fields
  python3 - "$1" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
for k in ("seconds", "values_file"): del s[k]
for k in ("threads", "merged_shards"): s["run"].pop(k, None)
print(json.dumps(s, sort_keys=True, indent=1))
EOF
}

wait "$single_pid" || fail "the single run failed: $(tail -n 3 "$T/single.txt")"
core "$T/single.json" > "$T/single.core"

echo "1. shard 2 alone, stopped by --max-pairs 1000"
t1=$SECONDS
submit --array 2 -- --max-order 300 --max-pairs 1000
states=$(wait_jobs 120 "$array_job" "$merge_job")
echo "$states" | sed 's/^/  /'
grep -qx "${array_job}_2 FAILED" <<<"$states" || fail "task 2 did not fail"
grep -qx "$merge_job CANCELLED" <<<"$states" || fail "the merge job was not cancelled"
[ -e "$T/out/shard-2.state" ] || fail "no resume state for shard 2"
[ ! -e "$T/out/summary.json" ] || fail "a summary was written although shard 2 failed"
echo "   ok ($((SECONDS - t1)) s): task 2 failed with a resume state, merge cancelled"

echo "   a resubmission with other options is refused"
if "$submit" --shards 4 --out-dir "$T/out" --gyrores "$gyrores" -- --max-order 301 2>"$T/refused.err"; then
  fail "submit-sweep accepted other sweep options in the same directory"
fi
grep -q 'holds another sweep' "$T/refused.err" || fail "unexpected refusal: $(cat "$T/refused.err")"

echo "2. all 4 shards: --max-order 300"
t1=$SECONDS
submit -- --max-order 300
states=$(wait_jobs 120 "$array_job" "$merge_job")
echo "$states" | sed 's/^/  /'
[ "$(grep -c ' COMPLETED$' <<<"$states")" -eq 5 ] || fail "not every job completed"
grep -q "^shard 2/4: resuming from" "$T/out/logs/shard-2-job$array_job.out" || fail "shard 2 did not resume"
[ ! -e "$T/out/shard-2.state" ] || fail "shard 2 left its resume state"
[ "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["run"]["merged_shards"])' "$T/out/summary.json")" = 4 ] ||
  fail "summary.json is not a merge of 4 shards"
core "$T/out/summary.json" > "$T/merged.core"
cmp "$T/single.core" "$T/merged.core" || fail "the merged summary differs from the single run: $(diff "$T/single.core" "$T/merged.core" | head -n 20)"
echo "   ok ($((SECONDS - t1)) s): shard 2 resumed; merged summary == single run"

echo "3. task 1 again: complete, skipped; merged again"
t1=$SECONDS
rm "$T/out/summary.json"
submit --array 1 -- --max-order 300
states=$(wait_jobs 60 "$array_job" "$merge_job")
[ "$(grep -c ' COMPLETED$' <<<"$states")" -eq 2 ] || fail "not every job completed: $(tr '\n' ' ' <<<"$states")"
grep -q "^shard 1/4: already complete" "$T/out/logs/shard-1-job$array_job.out" || fail "shard 1 was not skipped"
core "$T/out/summary.json" > "$T/merged.core"
cmp "$T/single.core" "$T/merged.core" || fail "the second merge differs from the single run"
echo "   ok ($((SECONDS - t1)) s)"

echo "PASS: slurm sweep in $((SECONDS - t0)) s"
