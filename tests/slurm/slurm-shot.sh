#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A 40-frame shot rendered by a one-node Slurm cluster as a job array of 4 chunks, every frame
# (and coverage.csv) compared bit for bit with a single-process render of the whole range; then
# a flare-data set generated as a job array of 3 shards, compared with a one-process set.
# The test starts its own munged (own key and socket) and slurmctld + slurmd (own config, state
# and ports, bound to 127.0.0.1) in a temporary folder, and stops them when it ends. Exit 77
# (skipped) only when the daemons cannot start here, with the reason.
#   slurm-shot.sh FLAREKIT SAMPLES_DIR SBATCH_SCRIPT SYNTH_SBATCH_SCRIPT
set -euo pipefail
flarekit="$(realpath "$1")"
samples="$(realpath "$2")"
script="$(realpath "$3")"
synth_script="$(realpath "$4")"
work="$(mktemp -d /tmp/flarekit-slurm.XXXXXX)"
chmod 755 "$work"

skip() { echo "SKIPPED: $*" >&2; exit 77; }
for tool in munged slurmctld slurmd sbatch sinfo scontrol oiiotool; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/install-deps.sh installs it)"
done
[ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start jobs"

pids=()
cleanup() {
  if [ -n "${SLURM_CONF:-}" ]; then scontrol shutdown >/dev/null 2>&1 || true; fi
  sleep 1
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
  # munged is a daemon, not a child, so wait returns at once; it writes its seed file as it
  # exits, which would race the rm below. Up to 5 s for each to be gone.
  for p in "${pids[@]}"; do
    for _ in $(seq 1 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
  done
  rm -rf "$work"
}
trap cleanup EXIT

# Two free TCP ports on loopback for slurmctld and slurmd: random ones nothing answers on.
freePort() {
  local p
  while :; do
    p=$((20000 + RANDOM % 20000))
    (echo >"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }
  done
}
ctldPort=$(freePort)
slurmdPort=$(freePort)
while [ "$slurmdPort" = "$ctldPort" ]; do slurmdPort=$(freePort); done

# munge: a private key and socket (never the system's).
mkdir -p "$work/munge"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.sock" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
  --seed-file="$work/munge/munged.seed" || skip "munged did not start: $(tail -1 "$work/munge/munged.log" 2>/dev/null)"
pids+=("$(cat "$work/munge/munged.pid")")

mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<CONF
ClusterName=flarekit-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctldPort
SlurmdPort=$slurmdPort
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SchedulerType=sched/backfill
NodeName=flarenode NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=shots Nodes=flarenode Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N flarenode -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 &
pids+=($!)
for ((i = 0; i < 60; i++)); do
  state=$(sinfo -h -n flarenode -o %t 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.5
done
[ "$state" = "idle" ] || skip "the Slurm node did not come up (state '${state}'): $(tail -2 "$work/slurmd.log" "$work/slurmctld.log" 2>/dev/null | tr '\n' ' ')"

# The shot: 40 frames, a light that moves along a track behind a foreground edge that moves too.
mkdir -p "$work/in" "$work/ref" "$work/farm"
oiiotool "$samples/sunset-hdr.exr" --resize 320x180 -o "$work/src.exr"
printf 'frame,x,y,intensity\n1,40,60,1\n40,280,100,2\n' >"$work/track.csv"
for ((f = 1; f <= 40; f++)); do
  cp "$work/src.exr" "$(printf "$work/in/shot.%04d.exr" "$f")"
done
# The matte of frame f covers x 0 to 8 f: one oiiotool for the 40 frames (one per frame was
# half of this test's time).
oiiotool --frames 1-40 --create 320x180 1 --box:color=1:fill=1 "0,0,{FRAME_NUMBER*8},179" \
  -o "$work/in/matte.%04d.exr"
cmd=(apply "$work/in/shot.####.exr" --light-track "$work/track.csv" --matte
  "$work/in/matte.####.exr" --light-radius 12)
"$flarekit" "${cmd[@]}" -o "$work/ref/out.####.exr" 2>"$work/ref.log"

# The farm: 4 tasks of 10 frames, 2 at a time; sbatch --wait returns when all are done.
(cd "$work" && sbatch --wait --array=0-3%2 --cpus-per-task=1 "$script" 1 40 10 -- \
  "$flarekit" "${cmd[@]}" -o "$work/farm/out.####.exr") || {
  echo "sbatch failed; task logs:" >&2
  cat "$work"/flare-shot-*.log >&2 || true
  exit 1
}
bad=0
for ((f = 1; f <= 40; f++)); do
  name=$(printf "out.%04d.exr" "$f")
  cmp -s "$work/ref/$name" "$work/farm/$name" || { echo "frame $f differs from the one-process render" >&2; bad=1; }
done
cmp -s "$work/ref/coverage.csv" "$work/farm/coverage.csv" || { echo "coverage.csv differs" >&2; bad=1; }
[ "$(ls "$work"/flare-shot-*.log | wc -l)" -eq 4 ] || { echo "expected 4 task logs" >&2; bad=1; }
[ "$bad" -eq 0 ] && echo "40 frames from 4 Slurm tasks, bit-identical to one process"

# The flare-data generator as a job array of 3 shards (examples/slurm/synth-array.sbatch):
# the same files as one process makes.
synth=(synth --count 24 --size 64x48 --seed 5)
"$flarekit" "${synth[@]}" --out "$work/synth-ref" 2>>"$work/ref.log"
(cd "$work" && sbatch --wait --array=0-2 --cpus-per-task=1 "$synth_script" -- \
  "$flarekit" "${synth[@]}" --out "$work/synth-farm") || {
  echo "sbatch (synth) failed; task logs:" >&2
  cat "$work"/flare-synth-*.log >&2 || true
  exit 1
}
if diff -r "$work/synth-ref" "$work/synth-farm" >&2; then
  echo "24 samples from 3 Slurm tasks, bit-identical to one process"
else
  echo "the Slurm shards' samples differ from the one-process set" >&2
  bad=1
fi
exit "$bad"
