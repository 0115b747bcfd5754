#!/bin/bash
# End to end on a real Slurm: starts a one-node cluster on this machine
# (munged, slurmctld and slurmd from Debian's munge and slurm-wlm, with a
# generated configuration, localhost only, private socket, ports and state
# in a temporary folder), submits through tools/farm/submit.sh a 4-tile
# still and a 4-frame turntable as array tasks, merges the tiles in the
# dependent job, and checks the results against single-process renders;
# a failing tile must cancel its merge.
# Needs root (munged runs as the munge user, the Slurm daemons as root).
# A cluster that cannot start fails the test; the daemons are stopped
# however it ends.
#   slurm_end_to_end.sh FACET REPOSITORY
set -euo pipefail
facet=$1 repo=$2
fail() {
  echo "slurm_end_to_end: FAILED: $*" >&2
  for log in "$work"/*.log "$work"/munge/*.log; do
    [[ -f $log ]] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
  done
  exit 1
}
for tool in munged slurmctld slurmd sbatch sinfo runuser python3 idiff; do
  command -v "$tool" >/dev/null || { echo "slurm_end_to_end: FAILED: $tool is not installed (tools/setup.sh installs munge and slurm-wlm)" >&2; exit 1; }
done
[[ $(id -u) == 0 ]] || { echo "slurm_end_to_end: FAILED: the cluster's daemons need root" >&2; exit 1; }

# Every channel of two EXRs bit for bit (OpenImageIO's idiff).
same_pixels() { idiff -q -fail 0 -failpercent 0 -warn 0 "$1" "$2" >/dev/null 2>&1; }

work=$(mktemp -d /tmp/facet-slurm.XXXXXX)
chmod 755 "$work"
stop() {
  for pid_file in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [[ -f $pid_file ]] || continue
    pid=$(cat "$pid_file")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap stop EXIT

# munged: a key of its own and a socket in the work folder.
mkdir -m 755 "$work/munge"
head -c 1024 /dev/urandom >"$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
chown -R munge:munge "$work/munge"
socket=$work/munge/munge.socket
runuser -u munge -- munged --key-file="$work/munge/munge.key" --socket="$socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" ||
  fail "munged did not start"

host=$(hostname -s)
read -r controller_port node_port < <(python3 -c '
import socket
ports = []
for _ in range(2):
    s = socket.socket(); s.bind(("127.0.0.1", 0)); ports.append(s); 
print(*[s.getsockname()[1] for s in ports])')
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=facettest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$controller_port
SlurmdPort=$node_port
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
SchedulerType=sched/builtin
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
DependencyParameters=kill_invalid_depend
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=10 State=UP
CONF
mkdir "$work/state" "$work/spool"
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" -N "$host" || fail "slurmd did not start"
# The node's start is waited for, not timed: the deadline, far beyond a start
# on a busy machine and below the test's ctest TIMEOUT, only catches a hang.
deadline=$((SECONDS + 300))
until [[ $(sinfo -h -N -o %T 2>/dev/null) == idle || $SECONDS -ge $deadline ]]; do sleep 0.2; done
[[ $(sinfo -h -N -o %T 2>/dev/null) == idle ]] || fail "the node is not idle: $(sinfo -N 2>&1)"

out=$work/out
mkdir -m 777 "$out"
scene=$repo/scenes/examples/superball.obj
common=(--size 48x40 --spp 4 --backend cpu)
# --time: a job that hangs ends (a job takes seconds, its limit is minutes).
export FACET=$facet FACET_SBATCH_OPTIONS="--cpus-per-task=1 --time=5"

# A 4-tile still, merged by the dependent job.
"$repo/tools/farm/submit.sh" --wait tiles 4 "$out/still.exr" --png "$out/still.png" -- "$scene" "${common[@]}" ||
  fail "the tiled still's jobs failed"
"$facet" render "$scene" "${common[@]}" -o "$out/whole.exr" --quiet
for i in 0 1 2 3; do [[ -f $out/still.tile-$i-of-4.exr ]] || fail "tile $i was not written"; done
[[ -f $out/still.png ]] || fail "the merge wrote no PNG"
grep -q "double precision, 1 threads" "$out"/facet-*_0.log || fail "the tile ignored SLURM_CPUS_PER_TASK=1"
same_pixels "$out/whole.exr" "$out/still.exr" ||
  fail "the merged tiles differ from the single-process render"

# A 4-frame turntable, one array task per frame.
"$repo/tools/farm/submit.sh" --wait frames 0-3 "$out/turn_###.exr" -- "$scene" "${common[@]}" --turntable 4 ||
  fail "the turntable's jobs failed"
"$facet" render "$scene" "${common[@]}" --turntable 4 -o "$out/alone_###.exr" --quiet
for f in 000 001 002 003; do
  same_pixels "$out/alone_$f.exr" "$out/turn_$f.exr" ||
    fail "frame $f of the array differs from the same frame rendered in one process"
done
same_pixels "$out/turn_000.exr" "$out/turn_001.exr" &&
  fail "the turntable's frames 0 and 1 are the same image"
# A tile that fails cancels the merge, and --wait reports it.
if "$repo/tools/farm/submit.sh" --wait tiles 2 "$out/broken.exr" -- "$scene" "${common[@]}" --spp 3 >/dev/null 2>&1; then
  fail "a failed tile's merge was reported as done"
fi
[[ ! -e $out/broken.exr ]] || fail "a failed tile's merge wrote the image"
echo "slurm_end_to_end: passed"
