#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --emit slurm, run for real on a single-node Slurm cluster
# that this test starts itself (Debian's slurm-wlm and munge, installed by
# make deps): munged with a fresh key, slurmctld and slurmd from a
# slurm.conf naming this host, with every state, spool, log and socket in a
# temporary folder and ports of their own, and a small MaxArraySize (4).
# The emitted script submits the job arrays and the merge job (afterany);
# the merged files must equal the one-machine sweep's, also for folders,
# presets and --set values whose names hold what a shell would read (blanks,
# quotes, $(...), backquotes, newlines, Slurm's %A): no command in them
# runs.  A shard cancelled (scancel) makes the merge job fail naming it; the
# same --emit then submits only that shard, and the files come out equal.
# More shards than MaxArraySize go in several arrays.  The daemons are
# stopped by the pids they wrote.
# Needs root (slurmd runs jobs as their user; munged and slurm as root here).
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
set -u
BIN=${HYBOUNCE_BIN:-build/hybounce}
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
# noprov FILE: FILE but for its provenance line "; hybounce V (commit C): COMMAND",
# which names the command that wrote it
noprov() { grep -v '^; hybounce .*(commit .*): ' "$1"; }
ok() { echo "ok - $1"; }
notok() {
	echo "not ok - $1"
	[ $# -gt 1 ] && [ -f "$2" ] && sed 's/^/# /' "$2" | tail -n 20
	return 0
}
if [ "$(id -u)" != 0 ]; then
	echo "ok # SKIP Slurm sweep: starting slurmctld, slurmd and munged needs root"
	exit 0
fi
for c in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
	if ! command -v $c >/dev/null 2>&1 && [ ! -x /usr/sbin/$c ]; then
		notok "$c is installed (make deps installs slurm-wlm and munge)"
		exit 0
	fi
done
PATH=$PATH:/usr/sbin

T=$(mktemp -d /tmp/hybounce-slurm.XXXXXX)
chmod 755 "$T"
stop() {
	for p in slurmd slurmctld munged; do
		[ -f "$T/$p.pid" ] && kill "$(cat "$T/$p.pid")" 2>/dev/null
	done
	i=0
	while [ $i -lt 50 ]; do
		alive=0
		for p in slurmd slurmctld munged; do
			[ -f "$T/$p.pid" ] && kill -0 "$(cat "$T/$p.pid")" 2>/dev/null && alive=1
		done
		[ $alive = 0 ] && break
		i=$((i + 1))
		sleep 0.1
	done
	rm -rf "$T"
}
trap stop EXIT
H=$(hostname -s)
# Ports of our own, away from a real cluster's 6817/6818.
base=$((20000 + $$ % 20000))

mkdir -p "$T/state" "$T/spool" "$T/log"
dd if=/dev/urandom of="$T/munge.key" bs=1024 count=1 2>/dev/null
chmod 600 "$T/munge.key"
if ! munged -f --key-file="$T/munge.key" --socket="$T/munge.sock" --pid-file="$T/munged.pid" \
    --log-file="$T/log/munged.log" --seed-file="$T/munged.seed" 2>"$T/log/munged.err"; then
	notok "munged starts" "$T/log/munged.err"
	exit 0
fi
cat >"$T/slurm.conf" <<CONF
ClusterName=hybounce-test
SlurmctldHost=$H
SlurmctldPort=$base
SlurmdPort=$((base + 1))
AuthType=auth/munge
AuthInfo=socket=$T/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/log/slurmctld.log
SlurmdLogFile=$T/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SlurmdParameters=config_overrides
NodeName=$H CPUs=$(nproc) RealMemory=1024 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
MaxArraySize=4
CONF
export SLURM_CONF="$T/slurm.conf"
if ! slurmctld -i -f "$SLURM_CONF" 2>"$T/log/ctld.err" || ! slurmd -f "$SLURM_CONF" 2>"$T/log/d.err"; then
	notok "slurmctld and slurmd start" "$T/log/slurmctld.log"
	exit 0
fi
i=0
while [ $i -lt 300 ]; do
	sinfo -h -o %t 2>/dev/null | grep -q '^idle' && break
	i=$((i + 1))
	sleep 0.2
done
if sinfo -h -o %t 2>/dev/null | grep -q '^idle'; then
	ok "a single-node Slurm cluster comes up ($H, $((i / 5)) s)"
else
	notok "a single-node Slurm cluster comes up" "$T/log/slurmctld.log"
	exit 0
fi

P=permanent-contact-shccl
set -- --vary "initial.x0=5um:60um:10" --vary "law.c=1e9,4.3e9"
"$BIN" sweep $P "$@" --quiet --out "$T/one" 2>"$T/err" || notok "one-machine sweep" "$T/err"
"$BIN" sweep $P "$@" --out "$T/cluster" --emit slurm --shards 4 >"$T/job.sh" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q -- '--array=0-3 ' "$T/job.sh" && grep -q 'SLURM_ARRAY_TASK_ID' "$T/job.sh" &&
    grep -q -- '--shard "$k/4"' "$T/job.sh" && grep -q -- '--dependency=afterany$deps' "$T/job.sh" &&
    grep -q -- "--merge .* --shards 4')\$" "$T/job.sh" && [ -d "$T/cluster/logs" ] && sh -n "$T/job.sh"; then
	ok "--emit slurm writes a job-array script (--array=0-3, shard from SLURM_ARRAY_TASK_ID, afterany merge, DIR/logs)"
else notok "--emit slurm writes a job-array script (exit $rc)" "$T/job.sh"; fi
(cd "$T" && sh "$T/job.sh") >"$T/submit" 2>&1
rc=$?
merge=$(sed -n 's/^submitted array jobs .* and merge job \([0-9]*\)$/\1/p' "$T/submit")
if [ $rc -eq 0 ] && [ -n "$merge" ]; then ok "sh job.sh submits the array and the merge job"
else notok "sh job.sh submits the array and the merge job (exit $rc)" "$T/submit"; exit 0; fi
i=0
while [ $i -lt 600 ]; do
	[ -z "$(squeue -h 2>/dev/null)" ] && break
	i=$((i + 1))
	sleep 0.2
done
state=$(scontrol show job "$merge" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p')
nocpu() { sed 's/,[^,]*$//' "$1"; }
# A sweep.preset but for its provenance line (which names the command).
if [ "$state" = COMPLETED ] && [ -f "$T/cluster/runs.csv" ] &&
    nocpu "$T/one/runs.csv" >"$T/a" && nocpu "$T/cluster/runs.csv" >"$T/b" && cmp -s "$T/a" "$T/b" &&
    cmp -s "$T/one/collisions.csv" "$T/cluster/collisions.csv"; then
	ok "Slurm ran the 4 shards and the merge: runs.csv and collisions.csv equal the one-machine sweep"
else
	notok "Slurm ran the shards and the merge (merge job $merge: ${state:-unknown})" "$T/log/slurmctld.log"
	cat "$T"/cluster/logs/*.out 2>/dev/null | sed 's/^/# /' | tail -n 20
fi
if [ -n "$(ls "$T/cluster/logs" | grep '^shard-[0-3]-of-4\.[0-9]*\.out$')" ] &&
    [ "$(ls "$T/cluster/logs" | grep -c '^shard-[0-3]-of-4\.[0-9]*\.out$')" -eq 4 ] &&
    [ -f "$T/cluster/logs/merge.$merge.out" ] && [ -z "$(ls "$T/cluster" | grep '^slurm-')" ]; then
	ok "the jobs' output is in DIR/logs (shard-K-of-4.JOB.out, merge.JOB.out)"
else notok "the jobs' output is in DIR/logs"; ls -l "$T/cluster" "$T/cluster/logs" | sed 's/^/# /'; fi

# wait_queue: until no job is left (pending or running), at most 2 minutes.
wait_queue() {
	i=0
	while [ $i -lt 600 ]; do
		[ -z "$(squeue -h 2>/dev/null)" ] && break
		i=$((i + 1))
		sleep 0.2
	done
}
job_state() { scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -n 1; }

# A shard killed: the jobs are submitted while the partition takes none,
# shard 2 is cancelled (scancel), then the partition opens.  The merge job
# runs anyway (afterany) and fails naming shard 2; the same --emit submits
# only shard 2, and the merged files equal the one-machine sweep's.
"$BIN" sweep $P --vary "initial.x0=5um:60um:10" --vary "law.c=1e9,4.3e9" --out "$T/kill" \
    --emit slurm --shards 4 --time 10:00 --mem 100M >"$T/kill.sh" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q -- "--time='10:00' --mem='100M' --chdir=" "$T/kill.sh"; then
	ok "--emit slurm --time 10:00 --mem 100M: every job asks for them"
else notok "--emit slurm --time --mem (exit $rc)" "$T/kill.sh"; fi
scontrol update PartitionName=debug State=DOWN
(cd "$T" && sh "$T/kill.sh") >"$T/submit" 2>&1
array=$(sed -n 's/^submitted array jobs \([0-9]*\) and merge job \([0-9]*\)$/\1/p' "$T/submit")
merge=$(sed -n 's/^submitted array jobs \([0-9]*\) and merge job \([0-9]*\)$/\2/p' "$T/submit")
[ -n "$array" ] && scancel "${array}_2"
scontrol update PartitionName=debug State=UP
wait_queue
state=$(job_state "$merge")
log="$T/kill/logs/merge.$merge.out"
if [ -n "$array" ] && [ "$state" = FAILED ] && [ ! -f "$T/kill/runs.csv" ] &&
    grep -q '1 of 4 shards incomplete: shard 2 (not started); 5 of 20 points missing' "$log"; then
	ok "a shard cancelled (scancel): the merge job runs anyway, fails and names it"
else
	notok "a shard cancelled: the merge job fails naming it (merge job ${merge:-none}: ${state:-unknown})" "$T/submit"
	[ -f "$log" ] && sed 's/^/# /' "$log"
fi
"$BIN" sweep "$T/kill/sweep.preset" --out "$T/kill" --emit slurm --shards 4 --time 10:00 \
    --mem 100M >"$T/kill2.sh" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c 'sbatch --parsable --job-name=hybounce-sweep' "$T/kill2.sh")" -eq 1 ] &&
    grep -q -- '--array=2 ' "$T/kill2.sh" && grep -q '3 of 4 shards already done' "$T/err"; then
	ok "--emit slurm again on the folder: only shard 2 is submitted (--array=2)"
else notok "--emit slurm again: only shard 2 (exit $rc)" "$T/kill2.sh"; cat "$T/err" | sed 's/^/# /'; fi
(cd "$T" && sh "$T/kill2.sh") >"$T/submit" 2>&1
merge=$(sed -n 's/^submitted array jobs .* and merge job \([0-9]*\)$/\1/p' "$T/submit")
wait_queue
state=$(job_state "$merge")
if [ "$state" = COMPLETED ] && nocpu "$T/one/runs.csv" >"$T/a" && nocpu "$T/kill/runs.csv" >"$T/b" &&
    cmp -s "$T/a" "$T/b" && cmp -s "$T/one/collisions.csv" "$T/kill/collisions.csv"; then
	ok "the resubmitted shard and the merge: runs.csv and collisions.csv equal the one-machine sweep"
else notok "the resubmitted shard and the merge (merge job ${merge:-none}: ${state:-unknown})" "$T/submit"; fi

# More shards than MaxArraySize (4 in slurm.conf, read from scontrol): 10
# shards in arrays of indices 0-3, 0-3 and 0-1 (shards 0-3, 4-7, 8-9).
"$BIN" sweep $P --vary "initial.x0=5um:60um:10" --vary "law.c=1e9,4.3e9" --out "$T/big" \
    --emit slurm --shards 10 >"$T/big.sh" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c 'sbatch --parsable --job-name=hybounce-sweep' "$T/big.sh")" -eq 3 ] &&
    grep -q 'at most 4 tasks (MaxArraySize)' "$T/big.sh" && grep -q 'k=$((8 + SLURM_ARRAY_TASK_ID))' "$T/big.sh"; then
	ok "--emit slurm --shards 10 with MaxArraySize 4 (from scontrol): 3 arrays"
else notok "--emit slurm --shards 10 with MaxArraySize 4: 3 arrays (exit $rc)" "$T/big.sh"; fi
(cd "$T" && sh "$T/big.sh") >"$T/submit" 2>&1
rc=$?
merge=$(sed -n 's/^submitted array jobs .* and merge job \([0-9]*\)$/\1/p' "$T/submit")
wait_queue
state=$(job_state "$merge")
if [ $rc -eq 0 ] && [ "$state" = COMPLETED ] && nocpu "$T/big/runs.csv" >"$T/b" && cmp -s "$T/a" "$T/b" &&
    cmp -s "$T/one/collisions.csv" "$T/big/collisions.csv"; then
	ok "Slurm ran 10 shards in 3 arrays and the merge: the files equal the one-machine sweep"
else notok "10 shards in 3 arrays (submit exit $rc, merge job ${merge:-none}: ${state:-unknown})" "$T/submit"; fi
# Hostile names: each is the folder (and the preset file's name, and part of
# a --set value) of a sweep emitted for Slurm; every script is submitted from
# $T, where a command in a name would touch a canary.
. "$(dirname "$0")/hostile_names.inc"
tried=0 injected=0 fails=0
i=0
while [ $i -lt "$hostile_count" ]; do
	name=$(hostile_name $i)
	mkdir -p "$T/h$i" && cp "$HYBOUNCE_PRESETS/$P.preset" "$T/h$i/$name.preset"
	set -- --vary "initial.x0=5um:60um:4" --set "scene.description=$(hostile_value $i)"
	"$BIN" sweep "$T/h$i/$name.preset" "$@" --quiet --out "$T/h$i/one" 2>"$T/err" ||
	    notok "folder $(hostile_show "$name"): one-machine sweep" "$T/err"
	if ! "$BIN" sweep "$T/h$i/$name.preset" "$@" --out "$T/h$i/$name" --emit slurm --shards 2 \
	    >"$T/h$i/job.sh" 2>"$T/err" || ! sh -n "$T/h$i/job.sh"; then
		notok "--emit slurm, folder $(hostile_show "$name"): a script" "$T/err"
	elif ! (cd "$T" && sh "$T/h$i/job.sh") >"$T/h$i/submit" 2>&1; then
		notok "--emit slurm, folder $(hostile_show "$name"): sh job.sh submits" "$T/h$i/submit"
	fi
	i=$((i + 1))
done
i=0
while [ $i -lt 900 ]; do
	[ -z "$(squeue -h 2>/dev/null)" ] && break
	i=$((i + 1))
	sleep 0.2
done
i=0
while [ $i -lt "$hostile_count" ]; do
	name=$(hostile_name $i)
	tried=$((tried + 1))
	merge=$(sed -n 's/^submitted array jobs .* and merge job \([0-9]*\)$/\1/p' "$T/h$i/submit" 2>/dev/null)
	state=$(scontrol show job "$merge" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p')
	if [ "$state" = COMPLETED ] && [ -f "$T/h$i/$name/runs.csv" ] &&
	    nocpu "$T/h$i/one/runs.csv" >"$T/a" && nocpu "$T/h$i/$name/runs.csv" >"$T/b" &&
	    cmp -s "$T/a" "$T/b" && cmp -s "$T/h$i/one/collisions.csv" "$T/h$i/$name/collisions.csv" &&
	    [ "$(noprov "$T/h$i/one/sweep.preset")" = "$(noprov "$T/h$i/$name/sweep.preset")" ]; then
		ok "--emit slurm, folder $(hostile_show "$name"): Slurm ran it, same files as one machine"
	else
		notok "--emit slurm, folder $(hostile_show "$name") (merge job ${merge:-none}: ${state:-unknown})" "$T/h$i/job.sh"
		fails=$((fails + 1))
		cat "$T/h$i/$name"/logs/*.out 2>/dev/null | sed 's/^/# /' | tail -n 10
	fi
	i=$((i + 1))
done
# The jobs ran in $T, the scripts were submitted from there; the folders too.
hostile_canaries "$T" || injected=1
if [ "$injected" -eq 0 ]; then
	ok "--emit slurm: names tried $tried, commands injected 0"
else
	notok "--emit slurm: names tried $tried, commands injected (a canary appeared under $T)"
fi
exit 0
