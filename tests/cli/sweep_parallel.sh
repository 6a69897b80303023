#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --emit parallel, run for real with GNU parallel on the local
# cores (and through --sshlogin ':', parallel's name for this machine): the
# merged files equal the one-machine sweep's, also for folders, presets and
# --set values whose names hold what a shell would read: blanks, quotes,
# $(...), backquotes, newlines, parallel's {} (no command in them runs).
# A shard that fails is named by the merge (the line exits non-zero), and
# the same --emit then runs only that shard.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"
if ! command -v parallel >/dev/null 2>&1; then
	notok "GNU parallel is installed (make deps installs it)"
	exit 0
fi
# parallel's one-time citation notice stays out of the test's way.
export HOME="$T/home"
mkdir -p "$HOME/.parallel" && touch "$HOME/.parallel/will-cite"

P=permanent-contact-shccl
set -- --vary "initial.x0=5um:60um:12" --vary "law.c=1e9,4.3e9"
"$BIN" sweep $P "$@" --quiet --out "$T/one" 2>"$T/err" || notok "one-machine sweep" "$T/err"

"$BIN" sweep $P "$@" --out "$T/par" --emit parallel --shards 5 >"$T/cmd" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(wc -l <"$T/cmd")" -eq 1 ] && grep -q '^HB_SWEEP_BIN=.* HB_SWEEP_DIR=.* parallel .* --shard {}/5'"'"' ::: 0 1 2 3 4; .* sweep --quiet --merge .* --shards 5$' "$T/cmd" &&
    [ -f "$T/par/sweep.preset" ] && [ ! -f "$T/par/runs.csv" ]; then
	ok "--emit parallel prints one command line (5 shards, then --merge) and writes sweep.preset"
else notok "--emit parallel prints one command line (exit $rc)" "$T/cmd"; fi
timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1
rc=$?
if [ $rc -eq 0 ] && same_sweep "$T/one" "$T/par" && [ -f "$T/par/shard-4-of-5.journal" ]; then
	ok "GNU parallel runs the 5 shards and the merge: files equal the one-machine sweep"
else notok "GNU parallel runs the shards and the merge (exit $rc)" "$T/out"; fi

"$BIN" sweep $P "$@" --out "$T/ssh" --emit parallel --shards 3 --sshlogin ':' >"$T/cmd" 2>"$T/err"
if grep -q " parallel --sshlogin ':' --env HB_SWEEP_BIN --env HB_SWEEP_DIR " "$T/cmd" &&
    timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1 && same_sweep "$T/one" "$T/ssh"; then
	ok "--emit parallel --sshlogin ':' (this machine as an ssh login) gives the same files"
else notok "--emit parallel --sshlogin ':' gives the same files" "$T/out"; cat "$T/cmd" | sed 's/^/# /'; fi
# A shard that fails: its journal cannot be written (a link into a folder
# that is not there), so shard 2 exits 1 while the others finish; the merge
# names it and the line exits 1.  Once the fault is gone, the same --emit
# runs shard 2 alone and the files equal the one-machine sweep's.
"$BIN" sweep $P --vary "initial.x0=5um:60um:12" --vary "law.c=1e9,4.3e9" --out "$T/fail" \
    --emit parallel --shards 5 >"$T/cmd" 2>"$T/err"
ln -s "$T/no such folder/x" "$T/fail/shard-2-of-5.journal"
timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1
rc=$?
if [ $rc -eq 1 ] && [ ! -f "$T/fail/runs.csv" ] && [ -s "$T/fail/shard-4-of-5.journal" ] &&
    grep -q 'merge: .*: 1 of 5 shards incomplete: shard 2 (not started); 5 of 24 points missing' "$T/out"; then
	ok "a shard fails: the others finish, the merge names shard 2, the line exits 1"
else notok "a shard fails: the merge names it (exit $rc)" "$T/out"; fi
rm -f "$T/fail/shard-2-of-5.journal"
"$BIN" sweep "$T/fail/sweep.preset" --out "$T/fail" --emit parallel --shards 5 >"$T/cmd" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "{}/5' ::: 2; " "$T/cmd" && grep -q '4 of 5 shards already done' "$T/err"; then
	ok "--emit parallel again on the folder: only shard 2 (::: 2)"
else notok "--emit parallel again: only shard 2 (exit $rc)" "$T/cmd"; show "$T/err"; fi
timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1
rc=$?
if [ $rc -eq 0 ] && same_sweep "$T/one" "$T/fail"; then
	ok "shard 2 run again and merged: the files equal the one-machine sweep"
else notok "shard 2 run again and merged (exit $rc)" "$T/out"; fi

# Hostile names: each is the folder (and the preset file's name, and part of
# a --set value) of a sweep emitted for parallel and run for real; a command
# in a name would touch a canary in $T (the scripts run there).
. "$(dirname "$0")/hostile_names.inc"
cd "$T" || exit 1
tried=0 injected=0
i=0
while [ $i -lt "$hostile_count" ]; do
	name=$(hostile_name $i)
	tried=$((tried + 1))
	mkdir -p "$T/h$i" && cp "$HYBOUNCE_PRESETS/$P.preset" "$T/h$i/$name.preset"
	set -- --vary "initial.x0=5um:60um:4" --set "scene.description=$(hostile_value $i)"
	"$BIN" sweep "$T/h$i/$name.preset" "$@" --quiet --out "$T/h$i/one" 2>"$T/err" ||
	    notok "folder $(hostile_show "$name"): one-machine sweep" "$T/err"
	"$BIN" sweep "$T/h$i/$name.preset" "$@" --out "$T/h$i/$name" --emit parallel --shards 3 \
	    >"$T/cmd" 2>"$T/err"
	rc=$?
	timeout 120 sh "$T/cmd" >"$T/out" 2>&1
	rc2=$?
	if [ $rc -eq 0 ] && [ $rc2 -eq 0 ] && same_sweep "$T/h$i/one" "$T/h$i/$name"; then
		ok "--emit parallel, folder $(hostile_show "$name"): runs as emitted, same files as one machine"
	else
		notok "--emit parallel, folder $(hostile_show "$name") (emit $rc, run $rc2)" "$T/out"
		show "$T/cmd"
	fi
	hostile_canaries "$T" || injected=$((injected + 1))
	i=$((i + 1))
done
# The last, worst name once more through --sshlogin ':' (--env carries it).
i=$((hostile_count - 1))
name=$(hostile_name $i)
"$BIN" sweep "$T/h$i/$name.preset" --vary "initial.x0=5um:60um:4" \
    --set "scene.description=$(hostile_value $i)" --out "$T/h$i/ssh $name" --emit parallel \
    --shards 2 --sshlogin ':' >"$T/cmd" 2>"$T/err" &&
    timeout 120 sh "$T/cmd" >"$T/out" 2>&1 && same_sweep "$T/h$i/one" "$T/h$i/ssh $name"
rc=$?
tried=$((tried + 1))
hostile_canaries "$T" || injected=$((injected + 1))
if [ $rc -eq 0 ]; then
	ok "--emit parallel --sshlogin ':', folder $(hostile_show "ssh $name"): same files"
else notok "--emit parallel --sshlogin ':', folder $(hostile_show "ssh $name")" "$T/out"; fi
if [ "$injected" -eq 0 ]; then
	ok "--emit parallel: names tried $tried, commands injected 0"
else
	notok "--emit parallel: names tried $tried, commands injected $injected"
fi
exit $((fails > 0))
